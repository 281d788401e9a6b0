// The retargeting permutation of Heitz & Belcour 2019, precomputed by simulated
// annealing (temporal blue noise thesis §2.4, Algorithm 5) and cached in a file.
//
// Usage (snippet: examples/snippets/bluenoise_retarget.cpp):
//
//     #include "prism/bluenoise/retarget.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     namespace bn = prism::bluenoise;
//     bn::Mask mask = bn::generateVoidAndCluster({.width = 16, .height = 16});
//     bn::RetargetOptions options;  // radius 6, sigma_i 2.1, sigma_s 1
//     options.schedule = bn::CoolingSchedule::Exponential;
//     options.epochs = 32;                                                      // of W*H proposed swaps
//     bn::frameShift(mask.width, mask.height, options.shiftX, options.shiftY);  // towards the next frame's mask
//     bn::RetargetResult r = bn::computeRetarget(mask, options);
//     bool cached = false;
//     bn::RetargetPermutation p = bn::loadOrComputeRetarget(mask, options, "out/retarget.bin", &cached);
//
// The state is a permutation `source` of the mask's pixels that starts as the identity;
// the retargeted texture is T(m) = B(source[m]). A move swaps the sources of two pixels
// less than `radius` apart, allowed only if both then come from within `radius` of home.
// The energy has two parts:
//   blue:   sum over pixel pairs p != q closer than 3 sigma_i of
//           exp(-|p - q|^2 / sigma_i^2 - |T(p) - T(q)|^(d/2) / sigma_s^2), d = 1
//           (thesis eq. 2.12 after Georgiev & Fajardo 2016: T must stay blue noise);
//   target: targetWeight * sum_p |T(p) - B(p + shift)|, the mask of the next frame,
//           shifted by the R2 step between frames (Algorithm 6), which T should become.
// A swap is accepted if it lowers the energy, else with probability exp(-dE / temperature).
// The start temperature accepts ~90% of uphill moves (Kirkpatrick 1983); the cooling
// schedules of thesis §2.4.1 run over `epochs` epochs of W*H moves, e = move / (W*H):
//   Hajek        T0 ln 2 / ln(2 + e)      (the thesis prints T0 log(1 + t), which rises;
//                                          Hajek 1988 divides by the logarithm)
//   Linear       T0 (1 - e / epochs)
//   Exponential  T0 alpha^e               (alpha 0.8..0.99; default 0.9)
//   Inverse      T0 / (1 + alpha e)
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "prism/bluenoise/mask.hpp"
#include "prism/bluenoise/sorting.hpp"

namespace prism::bluenoise {

enum class CoolingSchedule { Hajek, Linear, Exponential, Inverse };

CoolingSchedule parseCoolingSchedule(const std::string& name);  // throws std::invalid_argument
const char* coolingScheduleName(CoolingSchedule schedule);

struct RetargetOptions {
    int radius = 6;
    double sigmaI = 2.1;
    double sigmaS = 1.0;
    double targetWeight = 4.0;
    CoolingSchedule schedule = CoolingSchedule::Exponential;
    double alpha = 0.9;
    int epochs = 32;
    std::uint64_t seed = 1;
    // Shift (in mask pixels) from one frame's mask to the next: the R2 step (frameShift).
    // Left at 0 the identity already matches the target, and annealing can only move away.
    int shiftX = 0, shiftY = 0;
};

struct RetargetResult {
    RetargetPermutation permutation;
    double initialEnergy = 0.0, finalEnergy = 0.0;  // blue + target parts
    double initialTarget = 0.0, finalTarget = 0.0;  // the target part alone
    std::uint64_t moves = 0, accepted = 0;          // allowed proposals (of epochs * W * H), swaps made
};

// The R2 step between consecutive frames for a mask of this size (what applyRetarget's
// offsets advance by each frame).
void frameShift(int width, int height, int& shiftX, int& shiftY);

RetargetResult computeRetarget(const Mask& mask, const RetargetOptions& options);

// Reads `cache` when it holds the permutation for exactly this mask and these options,
// else computes it and writes the cache atomically. `fromCache` reports which.
RetargetPermutation loadOrComputeRetarget(const Mask& mask, const RetargetOptions& options,
                                          const std::filesystem::path& cache, bool* fromCache = nullptr);

}  // namespace prism::bluenoise
