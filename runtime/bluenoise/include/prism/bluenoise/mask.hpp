// A dither mask: one rank 0..N-1 per pixel (N = width * height, each rank once), as
// void-and-cluster produces it, and its conversions to 8-bit, 16-bit and 32-bit values.
//
// Usage (snippet: examples/snippets/bluenoise_mask.cpp):
//
//     #include "prism/bluenoise/mask.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     prism::bluenoise::Mask mask = prism::bluenoise::generateVoidAndCluster({.width = 16, .height = 16});
//     std::vector<std::uint16_t> png8 = prism::bluenoise::quantize(mask, 8);    // 0..255, uniform
//     std::vector<std::uint32_t> fixed = prism::bluenoise::fixedPoint32(mask);  // rank * 2^32 / N
//     std::uint32_t r = mask.rankAt(3, 5);
//
// quantize(mask, bits) maps rank r to floor(r * 2^bits / N): every level occurs
// floor(N / 2^bits) or that plus one times, exactly equally often when N is a multiple of
// 2^bits. fixedPoint32 is what the samplers use: a fraction of 2^32, so temporal offsets
// can be added as integers that wrap (no precision loss at frame 10^6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::bluenoise {

struct Mask {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> rank;  // row-major, row 0 at the top

    std::size_t size() const { return rank.size(); }
    std::uint32_t rankAt(int x, int y) const {
        return rank[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
    }
};

// floor(rank * 2^bits / N) for bits in 1..16.
std::vector<std::uint16_t> quantize(const Mask& mask, int bits);

// floor(rank * 2^32 / N): the mask as a 32-bit fixed-point fraction.
std::vector<std::uint32_t> fixedPoint32(const Mask& mask);

// Slice `frame` of a golden-ratio spatiotemporal stack: fixedPoint32(mask) + frame *
// 2^32 / phi (mod 2^32). Every slice is the same blue pattern shifted in value (still
// blue: thresholding it selects the union of two blue threshold sets), and every pixel's
// sequence over frames is the golden-ratio (R1) low-discrepancy sequence (temporal blue
// noise thesis §2.3.4).
std::vector<std::uint32_t> goldenRatioSlice(const Mask& mask, std::uint32_t frame);

// The golden-ratio step as a 32-bit fraction: round(2^32 / phi) = 0x9E3779B9.
inline constexpr std::uint32_t kGoldenRatioStep = 0x9E3779B9u;

}  // namespace prism::bluenoise
