// The three per-pixel samplers, bit-identical to modules/bluenoise/sampling.glsl.
//
// Usage (snippet: examples/snippets/bluenoise_samplers.cpp):
//
//     #include "prism/bluenoise/samplers.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     namespace bn = prism::bluenoise;
//     bn::Mask mask = bn::generateVoidAndCluster({.width = 16, .height = 16});
//     bn::SamplerTables tables = bn::SamplerTables::fromMask(mask);
//     std::uint32_t w = bn::sample(bn::SamplerKind::White, tables, 10, 20, 7, 0);  // pixel (10, 20), frame 7, dim 0
//     std::uint32_t b = bn::sample(bn::SamplerKind::BlueNoise, tables, 10, 20, 7, 1);
//     float u = bn::toUnitFloat(b);  // [0, 1)
//
// - White: pcgHash(pcgHash(pcgHash(pcgHash(x) + y) + frame) + dim).
// - BlueNoise: the mask (as a 32-bit fraction) at the pixel shifted by dimension dim's
//   R2 offset (plastic-number sequence, temporal blue noise thesis §2.3.5, in 16-bit
//   fixed point), plus frame * temporalStep(dim) mod 2^32: every frame is blue, and
//   every pixel's sequence over frames is low-discrepancy. Even dimensions step by
//   2^32/phi (the golden ratio, the best 1D sequence: thesis §2.3.4); odd dimensions by
//   2^32 (sqrt(3) - 1) (continued fraction [0; 1, 2, 1, 2, ...], so also a good 1D
//   sequence) so that a pair (2k, 2k+1) is spread in 2D instead of lying on a line, as
//   one shared step would give. (R2's steps spread pairs a little better in 2D but are
//   poor alone: 32 frames of the 1/g sequence leave a gap of 0.128, golden 0.056.)
// - Sorted: the pixel's seed (from the sorting and retargeting passes, sorting.hpp)
//   hashed with the dimension, plus the same temporal offset.
// - Stack: slice (frame mod D) of a spatiotemporal stack of D masks
//   (generateSpatiotemporal), at the pixel shifted by dimension dim's R2 offset, plus
//   (frame / D) * temporalStep(dim) so later passes through the stack differ.
// All arithmetic is on 32-bit unsigned integers that wrap, so frame 10^6 (or 2^32 - 1)
// loses nothing. Pixels outside the tables wrap around (the mask tiles the screen).
#pragma once

#include <cstdint>
#include <vector>

#include "prism/bluenoise/mask.hpp"
#include "prism/bluenoise/random.hpp"

namespace prism::bluenoise {

enum class SamplerKind : std::uint32_t { White = 0, BlueNoise = 1, Sorted = 2, Stack = 3 };

// R2 steps as 32-bit fractions: round(2^32 / g) and round(2^32 / g^2), g = 1.3247179572
// (the plastic number, x^3 = x + 1).
inline constexpr std::uint32_t kR2StepX = 0xC13FA9A9u;
inline constexpr std::uint32_t kR2StepY = 0x91E10DA5u;

// Per-frame steps: round(2^32 (sqrt(3) - 1)) for odd dimensions, 2^32/phi for even ones.
inline constexpr std::uint32_t kSqrt3Step = 0xBB67AE86u;
constexpr std::uint32_t temporalStep(std::uint32_t dim) {
    return (dim & 1u) ? kSqrt3Step : kGoldenRatioStep;
}

struct SamplerTables {
    int maskWidth = 1, maskHeight = 1;
    std::vector<std::uint32_t> mask{0};  // fixedPoint32 of a mask
    int seedWidth = 1, seedHeight = 1;
    std::vector<std::uint32_t> seeds{0};  // per-pixel seeds of the sorted sampler
    int stackWidth = 1, stackHeight = 1, stackDepth = 1;
    std::vector<std::uint32_t> stack{0};  // fixedPoint32 of each slice, slice after slice

    static SamplerTables fromMask(const Mask& mask);
    // Sets the stack from spatiotemporal slices (all of one size).
    void setStack(const std::vector<Mask>& slices);
};

std::uint32_t whiteSample(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t dim);
std::uint32_t blueNoiseSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                              std::uint32_t dim);
std::uint32_t sortedSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                           std::uint32_t dim);
std::uint32_t stackSample(const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                          std::uint32_t dim);
std::uint32_t sample(SamplerKind kind, const SamplerTables& t, std::uint32_t x, std::uint32_t y, std::uint32_t frame,
                     std::uint32_t dim);

// Dimension dim's R2 offset into a width x height mask.
void r2Offset(std::uint32_t index, int width, int height, std::uint32_t& dx, std::uint32_t& dy);

}  // namespace prism::bluenoise
