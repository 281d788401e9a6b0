// How far one water map is from another of the same terrain, whatever their grids: the
// depth resampled onto a common grid, then the mean and 95th percentile of the absolute
// depth difference and the wetted area (bench/water's trade compares every setting with
// a fine reference this way).
//
// Usage (snippet: examples/snippets/water_depth_comparison.cpp):
//
//     #include "prism/water/depth_comparison.hpp"
//     using namespace prism::water;
//     std::vector<float> fine(512 * 512, 0.002f), coarse(64 * 64, 0.0025f);
//     std::vector<float> common = resampleDepth(fine, 512, 512, 64, 64);  // 64 x 64 means
//     DepthComparison c = compareDepth(coarse, common);                   // meanAbsMm 0.5, both wetted
//
// Both grids cover the same square with nodes at its edges, as proceduralTerrain samples
// it: node x of a width-node row lies at x / (width - 1).
#pragma once

#include <span>
#include <vector>

namespace prism::water {

// Each node of the toWidth x toHeight grid takes the mean of the source nodes that lie in
// its cell, the half-open square [i - 1/2, i + 1/2) of its own node spacing around it;
// the source must be at least as fine in both directions and have at least 2 x 2 nodes
// (std::invalid_argument otherwise). Equal sizes copy.
std::vector<float> resampleDepth(std::span<const float> depth, int width, int height, int toWidth, int toHeight);

struct DepthComparison {
    double meanAbsMm = 0.0, p95AbsMm = 0.0;                // |depth - reference| over the cells, mm
    double wettedShare = 0.0, referenceWettedShare = 0.0;  // share of cells deeper than the wet depth
    // |wetted - reference wetted| / reference wetted (0 when neither is wet).
    double wettedAreaError() const;
};

// depth and reference on the same grid; a cell is wet when deeper than wetDepth metres.
DepthComparison compareDepth(std::span<const float> depth, std::span<const float> reference, double wetDepth = 0.001);

}  // namespace prism::water
