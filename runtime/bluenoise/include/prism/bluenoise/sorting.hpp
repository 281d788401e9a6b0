// The sorting and retargeting passes of Heitz & Belcour 2019 (temporal blue noise thesis
// §3.3, Algorithms 6-8): per-pixel seeds are permuted between frames so that the
// rendered error follows a blue-noise mask.
//
// Usage (snippet: examples/snippets/bluenoise_sorting.cpp):
//
//     #include "prism/bluenoise/sorting.hpp"
//     namespace bn = prism::bluenoise;
//     std::vector<std::uint32_t> seeds = bn::initialSeeds(8, 8, 1);
//     std::vector<float> values(64, 0.5f);    // frame t's pixel values (e.g. luminance)
//     std::vector<std::uint32_t> target(64);  // the mask's values for frame t+1 on screen
//     for (std::uint32_t i = 0; i < 64; ++i) target[i] = i * 0x04000000u;
//     bn::sortSeedsInBlocks(values, target, 8, 8, 4, seeds);  // 4x4 blocks
//
// sortSeedsInBlocks: inside every block x block tile (smaller at the right and bottom
// edges) the seed of the pixel with the k-th smallest value moves to the pixel with the
// k-th smallest target (ties broken by pixel index). Seeds never leave their block, so
// each is used exactly once per frame.
// applyRetarget (retarget.hpp computes the permutation): new[s] = old[s + d(s)], d read
// from the permutation at the screen pixel shifted by the frame's offset (Algorithm 6),
// inside the largest region of whole mask tiles taken as a torus (there the tiled
// permutation is a bijection; near its edges seeds wrap around); pixels outside that
// region keep their seeds. The result is always a permutation of the seeds.
#pragma once

#include <cstdint>
#include <vector>

namespace prism::bluenoise {

std::vector<std::uint32_t> initialSeeds(int width, int height, std::uint64_t seed);

void sortSeedsInBlocks(const std::vector<float>& values, const std::vector<std::uint32_t>& target, int width,
                       int height, int blockSize, std::vector<std::uint32_t>& seeds);

// A permutation of a maskWidth x maskHeight torus: source[m] is the mask pixel whose
// content moves to m.
struct RetargetPermutation {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> source;
};

void applyRetarget(const RetargetPermutation& permutation, int offsetX, int offsetY, int width, int height,
                   std::vector<std::uint32_t>& seeds);

}  // namespace prism::bluenoise
