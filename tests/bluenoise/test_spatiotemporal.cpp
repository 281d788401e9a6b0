// Spatiotemporal void-and-cluster stacks: every slice is a uniform blue-noise mask (bluer
// than golden-ratio slices of one mask), and every pixel's values over the slices are
// spread out (better than independent masks, not as well as golden-ratio offsets).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {

const std::vector<bn::Mask>& stack() {
    static const std::vector<bn::Mask> s = [] {
        const auto start = std::chrono::steady_clock::now();
        auto made = bn::generateSpatiotemporal({.width = 64, .height = 64}, 16);
        std::printf("64x64x16 stack: %.2f s\n",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        return made;
    }();
    return s;
}

bn::GrayImage gray(const bn::Mask& m) {
    return {m.width, m.height, 8, bn::quantize(m, 8)};
}

}  // namespace

// Largest gap in [0, 1) (cyclic) left by the first k values.
double largestGap(std::vector<double> v, std::size_t k) {
    v.resize(k);
    std::sort(v.begin(), v.end());
    double gap = 1.0 - v.back() + v.front();
    for (std::size_t i = 1; i < k; ++i) gap = std::max(gap, v[i] - v[i - 1]);
    return gap;
}

// Mean over pixels of the largest gap left by the first 16 slices' values.
double meanGap16(const std::vector<std::vector<double>>& slices) {
    double sum = 0.0;
    for (std::size_t i = 0; i < slices[0].size(); ++i) {
        std::vector<double> v;
        for (const auto& s : slices) v.push_back(s[i]);
        sum += largestGap(v, 16);
    }
    return sum / static_cast<double>(slices[0].size());
}

std::vector<double> unit(const std::vector<std::uint32_t>& fixed) {
    std::vector<double> v;
    for (std::uint32_t x : fixed) v.push_back(x / 4294967296.0);
    return v;
}

TEST(Spatiotemporal, SlicesAreUniformAndBluerThanGoldenRatioSlices) {
    ASSERT_EQ(stack().size(), 16u);
    double worstFast = 0.0, worstLf = 0.0;
    for (const bn::Mask& slice : stack()) {
        const bn::MaskMetrics m = bn::measureMask(gray(slice));
        EXPECT_TRUE(m.histogramUniform);
        worstFast = std::max(worstFast, m.filteredErrorSigma1);
        worstLf = std::max(worstLf, m.lowFrequencyPowerRatio);
    }
    // The alternative: golden-ratio slices of one 64x64 mask.
    const bn::Mask mask = bn::generateVoidAndCluster({.width = 64, .height = 64});
    double goldenFast = 0.0, goldenLf = 0.0;
    for (std::uint32_t t = 0; t < 16; ++t) {
        bn::GrayImage g{64, 64, 8, {}};
        for (std::uint32_t v : bn::goldenRatioSlice(mask, t)) g.values.push_back(static_cast<std::uint16_t>(v >> 24));
        goldenFast = std::max(goldenFast, bn::filteredErrorSigma1(g));
        goldenLf = std::max(goldenLf, bn::lowFrequencyPowerRatio(g));
    }
    std::printf("worst slice: spatiotemporal FAST %.4f LF %.5f; golden-ratio FAST %.4f LF %.5f\n", worstFast, worstLf,
                goldenFast, goldenLf);
    EXPECT_LT(worstFast, goldenFast);
    EXPECT_LT(worstFast, 0.047);
    EXPECT_LT(worstLf, 0.01);
    EXPECT_GT(goldenLf, 0.01);
}

TEST(Spatiotemporal, PixelSequencesAreSpreadOverTime) {
    std::vector<std::vector<double>> spatiotemporal, golden, independent;
    for (const bn::Mask& slice : stack()) spatiotemporal.push_back(unit(bn::fixedPoint32(slice)));
    const bn::Mask mask = bn::generateVoidAndCluster({.width = 64, .height = 64});
    for (std::uint32_t t = 0; t < 16; ++t) golden.push_back(unit(bn::goldenRatioSlice(mask, t)));
    for (std::uint64_t seed = 100; seed < 116; ++seed) {  // independent masks: white in time
        bn::VoidAndClusterOptions o{.width = 64, .height = 64};
        o.seed = seed;
        independent.push_back(unit(bn::fixedPoint32(bn::generateVoidAndCluster(o))));
    }
    const double st = meanGap16(spatiotemporal), g = meanGap16(golden), w = meanGap16(independent);
    std::printf("mean largest gap after 16 slices: spatiotemporal %.3f, golden ratio %.3f, independent %.3f\n", st, g,
                w);
    EXPECT_LT(st, 0.8 * w);
    EXPECT_LT(g, st);  // the trade: golden-ratio offsets spread each pixel's values best
}

TEST(Spatiotemporal, DepthOneIsThe2DMaskAndBadOptionsThrow) {
    EXPECT_EQ(bn::generateSpatiotemporal({.width = 24, .height = 16}, 1)[0].rank,
              bn::generateVoidAndCluster({.width = 24, .height = 16}).rank);
    EXPECT_THROW(bn::generateSpatiotemporal({.width = 8, .height = 8}, 0), std::invalid_argument);
    EXPECT_THROW(bn::generateSpatiotemporal({.width = 8, .height = 8}, 300), std::invalid_argument);
    EXPECT_THROW(bn::generateSpatiotemporal({.width = 8, .height = 8}, 4, 0.0), std::invalid_argument);
    const auto tiny = bn::generateSpatiotemporal({.width = 1, .height = 1}, 5);
    ASSERT_EQ(tiny.size(), 5u);
    for (const bn::Mask& m : tiny) EXPECT_EQ(m.rank[0], 0u);
}
