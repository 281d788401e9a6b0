// The usage example of prism/bluenoise/void_and_cluster.hpp, compiled and run by tests/snippets.
#include <algorithm>

// [snippet]
#include "prism/bluenoise/void_and_cluster.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::bluenoise::VoidAndClusterOptions options;
    options.width = 24;
    options.height = 16;  // non-square and non-power-of-two sizes are fine
    options.sigma = 1.5;  // Gaussian energy filter, in pixels
    options.seed = 7;     // same seed, same mask (bit for bit)
    prism::bluenoise::Mask mask = prism::bluenoise::generateVoidAndCluster(options);
    // [/snippet]
    // Every rank 0..N-1 once, and the same seed gives the same mask.
    std::vector<std::uint32_t> ranks = mask.rank;
    std::sort(ranks.begin(), ranks.end());
    for (std::size_t i = 0; i < ranks.size(); ++i)
        if (ranks[i] != i) return 1;
    const prism::bluenoise::Mask again = prism::bluenoise::generateVoidAndCluster(options);
    return mask.width == 24 && mask.height == 16 && ranks.size() == 24 * 16 && again.rank == mask.rank ? 0 : 1;
}
