// The usage example of prism/bluenoise/mask.hpp, compiled and run by tests/snippets.
#include <algorithm>

// [snippet]
#include "prism/bluenoise/mask.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::bluenoise::Mask mask = prism::bluenoise::generateVoidAndCluster({.width = 16, .height = 16});
    std::vector<std::uint16_t> png8 = prism::bluenoise::quantize(mask, 8);    // 0..255, uniform
    std::vector<std::uint32_t> fixed = prism::bluenoise::fixedPoint32(mask);  // rank * 2^32 / N
    std::uint32_t r = mask.rankAt(3, 5);
    // [/snippet]
    // N = 256 = 2^8: every 8-bit level exactly once, and 2^32 / N = 2^24.
    std::vector<std::uint16_t> levels = png8;
    std::sort(levels.begin(), levels.end());
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i] != i) return 1;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (fixed[i] != mask.rank[i] << 24 || png8[i] != mask.rank[i]) return 1;
    return levels.size() == 256 && r == mask.rank[5 * 16 + 3] ? 0 : 1;
}
