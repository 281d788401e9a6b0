// The procedural streak texture array that stands in for the Garg-Nayar database:
// Tariq's layout (5 x 9 x 10), brightness that depends on the light angles as the
// model says, distinct oscillation types, soft ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <set>

#include "prism/rain/streak_texture.hpp"

namespace prism::rain {
namespace {

const StreakTextureArray& texture() {
    static const StreakTextureArray t = generateStreakTextures();
    return t;
}

TEST(StreakTexture, HasTariqsLayout) {
    const auto& t = texture();
    EXPECT_EQ(t.layers, 450);
    EXPECT_EQ(t.width, 16);
    EXPECT_EQ(t.height, 64);
    EXPECT_EQ(t.bytes(), 450u * 16u * 64u);
    std::set<int> layers;
    for (int o = 0; o < kOscillationTypes; ++o)
        for (int a = 0; a < kThetaBins; ++a)
            for (int b = 0; b < kPhiBins; ++b) layers.insert(streakLayer(o, a, b));
    EXPECT_EQ(layers.size(), 450u);
    EXPECT_EQ(*layers.begin(), 0);
    EXPECT_EQ(*layers.rbegin(), 449);
    EXPECT_EQ(thetaOfBin(0), 10.0f);
    EXPECT_EQ(thetaOfBin(4), 170.0f);
    EXPECT_EQ(phiOfBin(8), 170.0f);
}

TEST(StreakTexture, IsDeterministic) {
    EXPECT_EQ(generateStreakTextures().texels, texture().texels);
}

TEST(StreakTexture, BackLitDropsAreBrighterThanFrontLit) {
    // phi = 170: the light is behind the drop (refraction through it, a lens); phi = 10:
    // the light is behind the viewer.
    for (int o = 0; o < kOscillationTypes; ++o) {
        const double back = texture().layerMean(streakLayer(o, 2, 8));
        const double front = texture().layerMean(streakLayer(o, 2, 0));
        EXPECT_GT(back, 2.0 * front) << "oscillation " << o;
    }
    EXPECT_NEAR(scatteringAngle(90.0f, 180.0f), 0.0f, 1e-3f);
    EXPECT_NEAR(scatteringAngle(90.0f, 0.0f), 180.0f, 1e-3f);
    EXPECT_GT(streakBrightness(90.0f, 170.0f), 0.8f);
    EXPECT_LT(streakBrightness(90.0f, 10.0f), 0.15f);
}

TEST(StreakTexture, RainbowAngleGlints) {
    // theta 50, phi 10: scattering angle ~139 deg, the primary rainbow.
    EXPECT_NEAR(scatteringAngle(50.0f, 10.0f), 139.0f, 1.0f);
    EXPECT_GT(streakBrightness(50.0f, 10.0f), 2.0f * streakBrightness(90.0f, 10.0f));
}

TEST(StreakTexture, OscillationTypesDiffer) {
    for (int o = 1; o < kOscillationTypes; ++o) {
        long diff = 0;
        const int a = streakLayer(0, 2, 4), b = streakLayer(o, 2, 4);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 16; ++x) diff += std::abs(texture().at(a, x, y) - texture().at(b, x, y));
        EXPECT_GT(diff, 16 * 64 * 2) << "oscillation " << o << " looks like type 0";
    }
}

TEST(StreakTexture, EndsAreSoftAndTheMiddleIsLit) {
    const int layer = streakLayer(3, 2, 8);
    int endMax = 0, middleMax = 0;
    for (int x = 0; x < 16; ++x) {
        endMax = std::max({endMax, int(texture().at(layer, x, 0)), int(texture().at(layer, x, 63))});
        for (int y = 24; y < 40; ++y) middleMax = std::max(middleMax, int(texture().at(layer, x, y)));
    }
    EXPECT_LT(endMax, 40);
    EXPECT_GT(middleMax, 150);
    // The edges across the streak are dark: a thin bright core.
    EXPECT_LT(texture().at(layer, 0, 32), texture().at(layer, 8, 32));
}

TEST(StreakTexture, BadSizeIsAnError) {
    EXPECT_THROW(generateStreakTextures(1, 64), std::invalid_argument);
    EXPECT_THROW(generateStreakTextures(16, 5000), std::invalid_argument);
    EXPECT_THROW(oscillationType(10), std::invalid_argument);
}

// One RGBA fetch per light holds the four layers of the bilinear blend between bins (R, G, B, A =
// (b, c), (b, c + 1), (b + 1, c), (b + 1, c + 1)), the neighbours clamped at the last bin.
TEST(StreakTexture, PackedCornersAreTheFourNeighbouringLayers) {
    const StreakTextureArray& t = texture();
    const std::vector<std::uint8_t> packed = packStreakBinCorners(t);
    ASSERT_EQ(packed.size(), 4 * t.texels.size());
    const std::size_t layerTexels = static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
    auto texel = [&](int layer, int channel, int x, int y) {
        const std::size_t i = static_cast<std::size_t>(layer) * layerTexels + static_cast<std::size_t>(y * t.width + x);
        return packed[4 * i + static_cast<std::size_t>(channel)];
    };
    for (int osc : {0, 7})
        for (int theta : {0, 2, kThetaBins - 1})
            for (int phi : {0, 5, kPhiBins - 1}) {
                const int theta1 = std::min(theta + 1, kThetaBins - 1), phi1 = std::min(phi + 1, kPhiBins - 1);
                const int corners[4] = {streakLayer(osc, theta, phi), streakLayer(osc, theta, phi1),
                                        streakLayer(osc, theta1, phi), streakLayer(osc, theta1, phi1)};
                for (int c = 0; c < 4; ++c)
                    for (auto [x, y] : {std::pair{0, 0}, std::pair{7, 31}, std::pair{t.width - 1, t.height - 1}})
                        ASSERT_EQ(texel(streakLayer(osc, theta, phi), c, x, y), t.at(corners[c], x, y))
                            << "osc " << osc << " theta " << theta << " phi " << phi << " channel " << c;
            }
}

}  // namespace
}  // namespace prism::rain
