// The usage example of prism/bluenoise/gl_soft_shadows.hpp, compiled and run by tests/snippets.
#include <algorithm>
#include <cmath>

// [snippet]
#include "prism/bluenoise/gl_soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
#include "prism/gl/gl_context.hpp"
// [/snippet]

int main() {
    // [snippet]
    namespace bn = prism::bluenoise;
    auto context = prism::gl::createContext();
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
    bn::RenderOptions options;
    options.width = options.height = 32;
    options.sampler = bn::SamplerKind::BlueNoise;
    bn::GlSoftShadows gpu(32, 32);
    bn::RealImage image = gpu.render(bn::SoftShadowScene::classic(), setup, options);
    double ms = gpu.lastFrameMilliseconds();  // GPU draw + readback of the last frame
    // [/snippet]
    // The CPU renders the same frame with the same (bit-identical) samples: only float
    // rounding differs.
    bn::StochasticSetup cpuSetup = bn::StochasticSetup::make(setup.mask);
    const bn::RealImage cpu = bn::renderSoftShadows(bn::SoftShadowScene::classic(), cpuSetup, options);
    if (image.width != 32 || image.height != 32 || image.values.size() != cpu.values.size() || !(ms >= 0.0)) return 1;
    double maxDifference = 0.0;
    for (std::size_t i = 0; i < cpu.values.size(); ++i)
        maxDifference = std::max(maxDifference, std::abs(image.values[i] - cpu.values[i]));
    return maxDifference < 1e-3 ? 0 : 1;
}
