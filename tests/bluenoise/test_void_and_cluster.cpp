// Void-and-cluster masks: ranks form a permutation, seeds are deterministic, the 128^2
// acceptance numbers of issue 13 hold, and the extremes (1x1, 1xN, sigma 0.3 and 10,
// non-square, non-power-of-two, invalid options) behave.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {

bn::Mask make(int w, int h, double sigma = 1.5, std::uint64_t seed = 1) {
    bn::VoidAndClusterOptions o;
    o.width = w;
    o.height = h;
    o.sigma = sigma;
    o.seed = seed;
    return bn::generateVoidAndCluster(o);
}

bool isPermutation(const bn::Mask& m) {
    std::vector<std::uint32_t> r = m.rank;
    std::sort(r.begin(), r.end());
    for (std::size_t i = 0; i < r.size(); ++i)
        if (r[i] != i) return false;
    return true;
}

bn::GrayImage gray8(const bn::Mask& m) {
    return {m.width, m.height, 8, bn::quantize(m, 8)};
}

// The 128^2 mask is the most expensive fixture: build it once.
const bn::Mask& mask128() {
    static const bn::Mask mask = make(128, 128);
    return mask;
}

}  // namespace

TEST(VoidAndCluster, RanksAreAPermutation) {
    EXPECT_TRUE(isPermutation(mask128()));
    EXPECT_EQ(mask128().size(), 128u * 128u);
}

TEST(VoidAndCluster, Acceptance128HistogramExactlyUniform) {
    const std::vector<std::uint16_t> v = bn::quantize(mask128(), 8);
    std::vector<int> counts(256, 0);
    for (auto x : v) ++counts[x];
    for (int c : counts) EXPECT_EQ(c, 64);
    EXPECT_TRUE(bn::histogramUniform(gray8(mask128())));
}

TEST(VoidAndCluster, Acceptance128LowFrequencyPowerRatio) {
    const double ratio = bn::lowFrequencyPowerRatio(gray8(mask128()));
    EXPECT_LE(ratio, 0.01);
    EXPECT_GE(ratio, 0.0);
}

TEST(VoidAndCluster, Acceptance128FilteredErrorBeatsWhiteNoise) {
    const double blue = bn::filteredErrorSigma1(gray8(mask128()));
    const double white = bn::filteredErrorSigma1(bn::whiteNoiseImage(128, 128, 8, 99));
    EXPECT_LE(blue, 0.046);
    EXPECT_NEAR(white, 0.114, 0.006);  // docs/references.md, "Blue-noise metrics": white noise ~0.114
}

TEST(VoidAndCluster, SameSeedSameMaskOtherSeedOtherMask) {
    const bn::Mask a = make(40, 24, 1.5, 5), b = make(40, 24, 1.5, 5), c = make(40, 24, 1.5, 6);
    EXPECT_EQ(a.rank, b.rank);
    EXPECT_NE(a.rank, c.rank);
}

TEST(VoidAndCluster, NonSquareNonPowerOfTwoSizes) {
    for (auto [w, h] : {std::pair{37, 91}, std::pair{96, 8}, std::pair{5, 3}, std::pair{2, 1}}) {
        const bn::Mask m = make(w, h);
        EXPECT_EQ(m.width, w);
        EXPECT_EQ(m.height, h);
        EXPECT_TRUE(isPermutation(m)) << w << "x" << h;
        // W*H = 768 (96x8) is a multiple of 256: exactly uniform; otherwise as even as possible.
        EXPECT_TRUE(bn::histogramUniform(gray8(m))) << w << "x" << h;
    }
    // A non-square mask is still blue: little low-frequency power.
    EXPECT_LT(bn::lowFrequencyPowerRatio(gray8(make(96, 40))), 0.05);
}

TEST(VoidAndCluster, ExtremeSizesOneByOneAndOneByN) {
    const bn::Mask one = make(1, 1);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one.rank[0], 0u);
    const bn::Mask line = make(1, 300);
    EXPECT_TRUE(isPermutation(line));
    const bn::Mask row = make(512, 1);
    EXPECT_TRUE(isPermutation(row));
    // A 1D blue sequence: neighbours differ a lot (no runs of similar ranks).
    double meanStep = 0.0;
    for (int x = 0; x < 512; ++x)
        meanStep += std::abs(static_cast<double>(row.rank[static_cast<std::size_t>(x)]) -
                             static_cast<double>(row.rank[static_cast<std::size_t>((x + 1) % 512)]));
    meanStep /= 512.0;
    EXPECT_GT(meanStep, 512.0 / 3.0 * 1.1);  // white noise: N/3
    for (const bn::Mask* m : {&one, &line, &row}) {
        const bn::MaskMetrics metrics = bn::measureMask(gray8(*m));
        EXPECT_TRUE(std::isfinite(metrics.lowFrequencyPowerRatio));
        EXPECT_TRUE(std::isfinite(metrics.filteredErrorSigma1));
        EXPECT_TRUE(std::isfinite(metrics.anisotropyDb));
    }
}

TEST(VoidAndCluster, ExtremeSigmas) {
    for (double sigma : {0.3, 10.0}) {
        const bn::Mask m = make(32, 32, sigma);
        EXPECT_TRUE(isPermutation(m)) << sigma;
        const bn::MaskMetrics metrics = bn::measureMask(gray8(m));
        EXPECT_TRUE(metrics.histogramUniform);
        EXPECT_TRUE(std::isfinite(metrics.lowFrequencyPowerRatio));
        EXPECT_TRUE(std::isfinite(metrics.filteredErrorSigma1));
        EXPECT_TRUE(std::isfinite(metrics.anisotropyDb));
    }
}

TEST(VoidAndCluster, InvalidOptionsThrowNamingTheOption) {
    auto message = [](int w, int h, double sigma) {
        try {
            make(w, h, sigma);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_NE(message(0, 5, 1.5).find("width"), std::string::npos);
    EXPECT_NE(message(5, 513, 1.5).find("height"), std::string::npos);
    EXPECT_NE(message(5, 5, 0.0).find("sigma"), std::string::npos);
    EXPECT_NE(message(5, 5, std::nan("")).find("sigma"), std::string::npos);
    EXPECT_NE(message(5, 5, INFINITY).find("sigma"), std::string::npos);
    EXPECT_NO_THROW(make(512, 1));
}
