// The scene's Monte Carlo effect on the CPU (see prism/scene/stochastic.hpp).
#include "prism/scene/stochastic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace prism::scene {

std::optional<bluenoise::SamplerKind> parseStochasticSampler(const std::string& name) {
    if (name == "white") return bluenoise::SamplerKind::White;
    if (name == "bluenoise") return bluenoise::SamplerKind::BlueNoise;
    if (name == "sorted") return bluenoise::SamplerKind::Sorted;
    return std::nullopt;
}

const char* stochasticSamplerName(bluenoise::SamplerKind kind) {
    switch (kind) {
        case bluenoise::SamplerKind::White: return "white";
        case bluenoise::SamplerKind::BlueNoise: return "bluenoise";
        case bluenoise::SamplerKind::Sorted: return "sorted";
        case bluenoise::SamplerKind::Stack: break;
    }
    return "stack";
}

StochasticRun prepareStochastic(const StochasticSettings& s, int width, int height) {
    namespace bn = prism::bluenoise;
    if (!parseStochasticSampler(stochasticSamplerName(s.sampler)))
        throw std::invalid_argument("stochastic: sampler must be white, bluenoise or sorted");
    if (s.spp < 1 || s.spp > static_cast<int>(kMaxStochasticSpp))
        throw std::invalid_argument("stochastic: spp must be 1.." + std::to_string(kMaxStochasticSpp));
    if (s.frame < 0 || s.frame > static_cast<int>(kMaxStochasticFrame))
        throw std::invalid_argument("stochastic: frame must be 0.." + std::to_string(kMaxStochasticFrame));
    if (s.frames < 1 || s.frames > static_cast<int>(kMaxStochasticFrames))
        throw std::invalid_argument("stochastic: frames must be 1.." + std::to_string(kMaxStochasticFrames));
    if (s.frame > 0 && s.frames > 1) throw std::invalid_argument("stochastic: give frame or frames > 1, not both");
    if (s.sampler == bn::SamplerKind::Sorted && s.frame > static_cast<int>(kMaxSortedFrame))
        throw std::invalid_argument("stochastic: the sorted sampler replays every frame before K; use frame <= " +
                                    std::to_string(kMaxSortedFrame));
    bn::VoidAndClusterOptions maskOptions;
    maskOptions.width = maskOptions.height = s.maskSize;
    maskOptions.seed = s.maskSeed;
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster(maskOptions));
    // Frame 0 alone never retargets; later frames of the sorted sampler do.
    const bool later = s.frames > 1 || s.frame > 0;
    if (s.sampler == bn::SamplerKind::Sorted && later && s.retargetEpochs > 0 && setup.mask.size() > 1) {
        bn::RetargetOptions r;
        r.shiftX = setup.shiftX;
        r.shiftY = setup.shiftY;
        r.epochs = s.retargetEpochs;
        setup.retarget = bn::computeRetarget(setup.mask, r).permutation;
    }
    bn::RenderOptions o;
    o.width = width;
    o.height = height;
    o.spp = s.spp;
    o.sampler = s.sampler;
    o.frame = s.frame;
    o.frames = s.frames;
    o.block = s.block;
    return {std::move(setup), o};
}

bluenoise::RealImage renderStochasticValues(const StochasticSettings& s, int width, int height) {
    StochasticRun run = prepareStochastic(s, width, height);
    return bluenoise::renderSoftShadows(s.light, run.setup, run.options);
}

image::Image8 renderStochastic(const StochasticSettings& s, int width, int height) {
    return toGreyImage(renderStochasticValues(s, width, height));
}

image::Image8 toGreyImage(const bluenoise::RealImage& values) {
    const int width = values.width, height = values.height;
    image::Image8 out(width, height, {0, 0, 0, 255});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double v = values.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                           static_cast<std::size_t>(x)];
            const auto g =
                static_cast<std::uint8_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0) * 255.0));
            out.set(x, y, {g, g, g, 255});
        }
    return out;
}

}  // namespace prism::scene
