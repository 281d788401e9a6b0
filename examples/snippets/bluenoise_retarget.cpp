// The usage example of prism/bluenoise/retarget.hpp, compiled and run by tests/snippets.
#include <algorithm>
#include <filesystem>

// [snippet]
#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
// [/snippet]

int main() {
    std::filesystem::remove("out/retarget.bin");  // so the first call computes
    // [snippet]
    namespace bn = prism::bluenoise;
    bn::Mask mask = bn::generateVoidAndCluster({.width = 16, .height = 16});
    bn::RetargetOptions options;  // radius 6, sigma_i 2.1, sigma_s 1
    options.schedule = bn::CoolingSchedule::Exponential;
    options.epochs = 32;                                                      // of W*H proposed swaps
    bn::frameShift(mask.width, mask.height, options.shiftX, options.shiftY);  // towards the next frame's mask
    bn::RetargetResult r = bn::computeRetarget(mask, options);
    bool cached = false;
    bn::RetargetPermutation p = bn::loadOrComputeRetarget(mask, options, "out/retarget.bin", &cached);
    // [/snippet]
    // A permutation of the 256 pixels, deterministic (the same as computeRetarget's), that
    // lowers the energy and brings the texture much closer to the next frame's mask (16x16,
    // 32 epochs: target 342 -> 165); the second load comes from the file.
    std::vector<std::uint32_t> sorted = r.permutation.source;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i)
        if (sorted[i] != i) return 1;
    bool cachedAgain = false;
    const bn::RetargetPermutation again = bn::loadOrComputeRetarget(mask, options, "out/retarget.bin", &cachedAgain);
    return sorted.size() == 256 && !cached && cachedAgain && p.source == r.permutation.source &&
                   again.source == p.source && r.finalEnergy < r.initialEnergy &&
                   r.finalTarget < 0.6 * r.initialTarget && r.initialTarget > 0.0 && r.accepted > 0 &&
                   r.accepted <= r.moves
               ? 0
               : 1;
}
