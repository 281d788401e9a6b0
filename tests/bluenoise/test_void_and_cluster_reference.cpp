// Differential test of void-and-cluster's accelerated search (per-row caches refreshed
// only where a splat could change them) against a plain reference that scans every pixel
// for every void and cluster. Both use the same seeded start and the same splat order, so
// the energies agree to the bit and the ranks must agree exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/bluenoise/random.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {

// Ulichney 1993 written out directly: full scans, no caches.
std::vector<std::uint32_t> referenceRanks(int w, int h, double sigma, std::uint64_t seed) {
    const int n = w * h;
    const int reach = static_cast<int>(std::ceil(sigma * std::sqrt(2.0 * std::log(1e6))));
    const int x0 = -std::min(reach, (w - 1) / 2), x1 = std::min(reach, w / 2);
    const int y0 = -std::min(reach, (h - 1) / 2), y1 = std::min(reach, h / 2);
    std::vector<double> energy(static_cast<std::size_t>(n), 0.0);
    std::vector<char> on(static_cast<std::size_t>(n), 0);
    auto splat = [&](std::vector<double>& e, std::vector<char>& o, int i, bool turnOn) {
        o[static_cast<std::size_t>(i)] = turnOn;
        const int x = i % w, y = i / w;
        for (int dy = y0; dy <= y1; ++dy)
            for (int dx = x0; dx <= x1; ++dx) {
                const int q = ((y + dy) % h + h) % h * w + ((x + dx) % w + w) % w;
                e[static_cast<std::size_t>(q)] +=
                    (turnOn ? 1.0 : -1.0) * std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
            }
    };
    auto find = [&](const std::vector<double>& e, const std::vector<char>& o, bool cluster) {
        int best = -1;
        for (int i = 0; i < n; ++i)
            if ((o[static_cast<std::size_t>(i)] != 0) == cluster &&
                (best < 0 || (cluster ? e[static_cast<std::size_t>(i)] > e[static_cast<std::size_t>(best)]
                                      : e[static_cast<std::size_t>(i)] < e[static_cast<std::size_t>(best)])))
                best = i;
        return best;
    };
    const int ones = std::max(1, static_cast<int>(0.1 * n));
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
    bn::SplitMix64 rng(seed);
    for (int i = 0; i < ones; ++i)
        std::swap(order[static_cast<std::size_t>(i)],
                  order[static_cast<std::size_t>(i + static_cast<int>(rng.below(static_cast<std::uint64_t>(n - i))))]);
    for (int i = 0; i < ones; ++i) splat(energy, on, order[static_cast<std::size_t>(i)], true);
    for (int it = 0; it < n; ++it) {
        const int c = find(energy, on, true);
        splat(energy, on, c, false);
        const int v = find(energy, on, false);
        splat(energy, on, v, true);
        if (v == c) break;
    }
    std::vector<std::uint32_t> rank(static_cast<std::size_t>(n));
    std::vector<double> e2 = energy;
    std::vector<char> o2 = on;
    for (int r = ones - 1; r >= 0; --r) {
        const int c = find(e2, o2, true);
        splat(e2, o2, c, false);
        rank[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(r);
    }
    for (int r = ones; r < n; ++r) {
        const int v = find(energy, on, false);
        splat(energy, on, v, true);
        rank[static_cast<std::size_t>(v)] = static_cast<std::uint32_t>(r);
    }
    return rank;
}

}  // namespace

TEST(VoidAndClusterReference, AcceleratedSearchMatchesFullScans) {
    for (auto [w, h, sigma] :
         {std::tuple{48, 40, 1.5}, std::tuple{64, 64, 1.5}, std::tuple{30, 7, 0.3}, std::tuple{20, 20, 10.0}}) {
        bn::VoidAndClusterOptions o;
        o.width = w;
        o.height = h;
        o.sigma = sigma;
        o.seed = 4;
        EXPECT_EQ(bn::generateVoidAndCluster(o).rank, referenceRanks(w, h, sigma, 4))
            << w << "x" << h << " sigma " << sigma;
    }
}
