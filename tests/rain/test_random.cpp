// The counter-based hash RNG shared by C++ and GLSL: values, range, uniformity and
// independence of channels (the GPU tests check the GLSL copy is bit-identical).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "prism/rain/random.hpp"

namespace prism::rain {
namespace {

TEST(RainRandom, IsAPureFunction) {
    static_assert(pcgHash(1u) == pcgHash(1u));
    static_assert(rainRandom(1u, 2u, 3u) != rainRandom(1u, 2u, 4u));
    EXPECT_EQ(rainRandom(7u, 100u, 3u), rainRandom(7u, 100u, 3u));
    EXPECT_NE(rainRandom(7u, 100u, 3u), rainRandom(8u, 100u, 3u));
    EXPECT_NE(rainRandom(7u, 100u, 3u), rainRandom(7u, 101u, 3u));
}

TEST(RainRandom, HashHasNoCollisionsOnAMillionCounters) {
    std::set<std::uint32_t> seen;
    for (std::uint32_t i = 0; i < (1u << 20); ++i) seen.insert(pcgHash(i));
    EXPECT_EQ(seen.size(), 1u << 20);  // PCG's permutation of a bijective LCG step is a bijection
}

TEST(RainRandom, UniformInUnitIntervalWithEvenBins) {
    constexpr int kBins = 16;
    constexpr std::uint32_t kN = 1u << 18;
    std::array<int, kBins> bins{};
    double sum = 0.0;
    for (std::uint32_t i = 0; i < kN; ++i) {
        const float u = rainUniform(1u, i, 0u);
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        sum += u;
        ++bins[static_cast<std::size_t>(u * kBins)];
    }
    EXPECT_NEAR(sum / kN, 0.5, 0.003);
    double chi2 = 0.0;
    const double expected = static_cast<double>(kN) / kBins;
    for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
    EXPECT_LT(chi2, 37.7);  // chi-square, 15 degrees of freedom, p = 0.001
}

TEST(RainRandom, ChannelsAreUncorrelated) {
    constexpr std::uint32_t kN = 1u << 16;
    double sx = 0, sy = 0, sxy = 0, sxx = 0, syy = 0;
    for (std::uint32_t i = 0; i < kN; ++i) {
        const double x = rainUniform(3u, i, 0u), y = rainUniform(3u, i, 1u);
        sx += x;
        sy += y;
        sxy += x * y;
        sxx += x * x;
        syy += y * y;
    }
    const double cov = sxy / kN - (sx / kN) * (sy / kN);
    const double r = cov / std::sqrt((sxx / kN - (sx / kN) * (sx / kN)) * (syy / kN - (sy / kN) * (sy / kN)));
    EXPECT_LT(std::fabs(r), 0.02);
}

}  // namespace
}  // namespace prism::rain
