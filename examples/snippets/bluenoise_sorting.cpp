// The usage example of prism/bluenoise/sorting.hpp, compiled and run by tests/snippets.
#include <algorithm>

// [snippet]
#include "prism/bluenoise/sorting.hpp"
// [/snippet]

int main() {
    // [snippet]
    namespace bn = prism::bluenoise;
    std::vector<std::uint32_t> seeds = bn::initialSeeds(8, 8, 1);
    std::vector<float> values(64, 0.5f);    // frame t's pixel values (e.g. luminance)
    std::vector<std::uint32_t> target(64);  // the mask's values for frame t+1 on screen
    for (std::uint32_t i = 0; i < 64; ++i) target[i] = i * 0x04000000u;
    bn::sortSeedsInBlocks(values, target, 8, 8, 4, seeds);  // 4x4 blocks
    // [/snippet]
    // All values tie (broken by pixel index) and the target rises with the pixel index, so
    // every seed stays where it was.
    if (seeds != bn::initialSeeds(8, 8, 1)) return 1;
    // With values falling with the pixel index (target still rising) each 4x4 block's seeds
    // reverse: the seeds at (0, 0) and (3, 3) swap.
    std::vector<std::uint32_t> start = bn::initialSeeds(8, 8, 1);
    std::vector<std::uint32_t> moved = start;
    for (int i = 0; i < 64; ++i) values[static_cast<std::size_t>(i)] = static_cast<float>(64 - i);
    bn::sortSeedsInBlocks(values, target, 8, 8, 4, moved);
    std::vector<std::uint32_t> a = start, b = moved;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b && moved[0] == start[3 * 8 + 3] && moved[3 * 8 + 3] == start[0] ? 0 : 1;
}
