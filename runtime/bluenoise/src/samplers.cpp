// CPU reference of the samplers in modules/bluenoise/sampling.glsl (same integer steps).
#include "prism/bluenoise/samplers.hpp"

#include <stdexcept>

namespace prism::bluenoise {

SamplerTables SamplerTables::fromMask(const Mask& mask) {
    SamplerTables t;
    t.maskWidth = mask.width;
    t.maskHeight = mask.height;
    t.mask = fixedPoint32(mask);
    t.seedWidth = mask.width;
    t.seedHeight = mask.height;
    t.seeds.resize(mask.size());
    for (std::size_t i = 0; i < t.seeds.size(); ++i) t.seeds[i] = pcgHash(static_cast<std::uint32_t>(i) + 0x5EEDu);
    return t;
}

void SamplerTables::setStack(const std::vector<Mask>& slices) {
    if (slices.empty()) throw std::invalid_argument("SamplerTables::setStack: no slices");
    stackWidth = slices[0].width;
    stackHeight = slices[0].height;
    stackDepth = static_cast<int>(slices.size());
    stack.clear();
    for (const Mask& m : slices) {
        if (m.width != stackWidth || m.height != stackHeight)
            throw std::invalid_argument("SamplerTables::setStack: the slices differ in size");
        const std::vector<std::uint32_t> v = fixedPoint32(m);
        stack.insert(stack.end(), v.begin(), v.end());
    }
}

void r2Offset(std::uint32_t index, int width, int height, std::uint32_t& dx, std::uint32_t& dy) {
    // 16-bit fraction times a size below 2^16: fits 32 bits, as in GLSL without 64-bit ints.
    dx = (((index * kR2StepX) >> 16u) * static_cast<std::uint32_t>(width)) >> 16u;
    dy = (((index * kR2StepY) >> 16u) * static_cast<std::uint32_t>(height)) >> 16u;
}

std::uint32_t whiteSample(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t dim) {
    return pcgHash(pcgHash(pcgHash(pcgHash(x) + y) + frame) + dim);
}

std::uint32_t blueNoiseSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                              std::uint32_t dim) {
    std::uint32_t dx = 0, dy = 0;
    r2Offset(dim, t.maskWidth, t.maskHeight, dx, dy);
    const std::uint32_t mx =
        (x % static_cast<std::uint32_t>(t.maskWidth) + dx) % static_cast<std::uint32_t>(t.maskWidth);
    const std::uint32_t my =
        (y % static_cast<std::uint32_t>(t.maskHeight) + dy) % static_cast<std::uint32_t>(t.maskHeight);
    return t.mask[my * static_cast<std::uint32_t>(t.maskWidth) + mx] + frame * temporalStep(dim);
}

std::uint32_t sortedSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                           std::uint32_t dim) {
    const std::uint32_t sx = x % static_cast<std::uint32_t>(t.seedWidth);
    const std::uint32_t sy = y % static_cast<std::uint32_t>(t.seedHeight);
    const std::uint32_t seed = t.seeds[sy * static_cast<std::uint32_t>(t.seedWidth) + sx];
    return pcgHash(pcgHash(seed) + dim) + frame * temporalStep(dim);
}

std::uint32_t stackSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                          std::uint32_t dim) {
    const auto w = static_cast<std::uint32_t>(t.stackWidth), h = static_cast<std::uint32_t>(t.stackHeight);
    const auto d = static_cast<std::uint32_t>(t.stackDepth);
    std::uint32_t dx = 0, dy = 0;
    r2Offset(dim, t.stackWidth, t.stackHeight, dx, dy);
    const std::uint32_t slice = frame % d, cycle = frame / d;
    const std::uint32_t sx = (x % w + dx) % w, sy = (y % h + dy) % h;
    return t.stack[(slice * h + sy) * w + sx] + cycle * temporalStep(dim);
}

std::uint32_t sample(SamplerKind kind, const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                     std::uint32_t dim) {
    switch (kind) {
        case SamplerKind::White: return whiteSample(x, y, frame, dim);
        case SamplerKind::BlueNoise: return blueNoiseSample(t, x, y, frame, dim);
        case SamplerKind::Sorted: return sortedSample(t, x, y, frame, dim);
        case SamplerKind::Stack: return stackSample(t, x, y, frame, dim);
    }
    return 0;
}

}  // namespace prism::bluenoise
