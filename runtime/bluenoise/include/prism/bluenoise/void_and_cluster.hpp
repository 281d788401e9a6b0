// Void-and-cluster dither masks (Ulichney 1993) on a torus, for any size 1x1..512x512.
//
// Usage (snippet: examples/snippets/bluenoise_void_and_cluster.cpp):
//
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     prism::bluenoise::VoidAndClusterOptions options;
//     options.width = 24;
//     options.height = 16;  // non-square and non-power-of-two sizes are fine
//     options.sigma = 1.5;  // Gaussian energy filter, in pixels
//     options.seed = 7;     // same seed, same mask (bit for bit)
//     prism::bluenoise::Mask mask = prism::bluenoise::generateVoidAndCluster(options);
//
// The energy of a pixel is the sum over "on" pixels of exp(-d^2 / (2 sigma^2)), d the
// toroidal distance; the kernel is cut where it falls below 1e-6. Energies are updated
// incrementally (one kernel splat per pixel turned on or off), and the void/cluster
// searches keep a per-row best that is recomputed only for rows a splat touched, so a
// 128^2 mask takes well under a second (bench/bluenoise reports the times).
// Invalid options (size outside 1..512, sigma not finite or <= 0) throw
// std::invalid_argument naming the option.
#pragma once

#include <cstdint>
#include <vector>

#include "prism/bluenoise/mask.hpp"

namespace prism::bluenoise {

struct VoidAndClusterOptions {
    int width = 64;
    int height = 64;
    double sigma = 1.5;
    std::uint64_t seed = 0;
    // Fraction of pixels in the initial random pattern (Ulichney: at most one half).
    double initialFraction = 0.1;
};

inline constexpr int kMaxMaskSide = 512;
inline constexpr int kMaxMaskDepth = 256;

Mask generateVoidAndCluster(const VoidAndClusterOptions& options);

// A spatiotemporal stack of `depth` masks (after Wolfe et al. 2022): void-and-cluster over
// the width x height x depth volume where two voxels interact only within a slice
// (Gaussian of options.sigma in pixels) or at the same pixel across slices (Gaussian of
// sigmaTime in slices, toroidal), then each slice ranked by the volume's ranks: every
// slice is a blue-noise mask and every pixel's values over the slices are spread out.
// Takes about depth times as long as one mask, and more (the searches scan all slices).
std::vector<Mask> generateSpatiotemporal(const VoidAndClusterOptions& options, int depth, double sigmaTime = 1.9);

}  // namespace prism::bluenoise
