// view::Fog: the animated noise array tiles in space and loops in time; billboards drift and
// stay around the camera; bad fog parameters are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "prism/rain/fog_billboards.hpp"
#include "prism/rain/rain_params.hpp"

namespace prism::rain {
namespace {

int texel(const FogNoiseArray& n, int layer, int x, int y) {
    return n.texels[(static_cast<std::size_t>(layer) * n.size + static_cast<std::size_t>(y)) * n.size +
                    static_cast<std::size_t>(x)];
}

TEST(FogNoise, TilesInSpaceAndLoopsInTime) {
    const FogNoiseArray n = generateFogNoise(64, 16, 7);
    ASSERT_EQ(n.texels.size(), 64u * 64u * 16u);
    // The step across the tile border is like any step between neighbours.
    double inner = 0.0, border = 0.0, step = 0.0, loop = 0.0;
    for (int l = 0; l < 16; ++l)
        for (int y = 0; y < 64; ++y) {
            inner += std::abs(texel(n, l, 31, y) - texel(n, l, 32, y));
            border += std::abs(texel(n, l, 63, y) - texel(n, l, 0, y));
        }
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            step += std::abs(texel(n, 7, x, y) - texel(n, 8, x, y));
            loop += std::abs(texel(n, 15, x, y) - texel(n, 0, x, y));
        }
    EXPECT_LT(border, 2.0 * inner + 64.0);
    EXPECT_LT(loop, 2.0 * step + 64.0);
    EXPECT_GT(step, 0.0);  // it does animate
    // It is patchy fog, not flat: both clear and dense texels.
    int low = 0, high = 0;
    for (auto v : n.texels) {
        low += v < 30;
        high += v > 200;
    }
    EXPECT_GT(low, 1000);
    EXPECT_GT(high, 1000);
}

TEST(FogBillboards, DriftAndStayAroundTheCamera) {
    FogBillboardParams p;
    p.count = 50;
    FogBillboardSimulation sim(p, glm::vec3(0.0f));
    const auto first = sim.billboards();
    glm::vec3 eye(0.0f, 1.7f, 0.0f);
    for (int i = 0; i < 200; ++i) {
        eye.x += 0.7f;
        sim.step(1.0f / 30.0f, eye, glm::vec3(4.0f, 0.0f, 0.0f));
        for (const auto& b : sim.billboards()) {
            ASSERT_LE(std::hypot(b.x - eye.x, b.z - eye.z), p.radius * 1.0001f);
            ASSERT_GE(b.y, p.minHeight);
            ASSERT_LE(b.y, p.maxHeight);
        }
    }
    EXPECT_NE(sim.billboards()[0], first[0]);
}

TEST(FogParams, BadValuesAreClearErrors) {
    SceneFog f;
    EXPECT_NO_THROW(validate(f));
    f.distance.density = -0.1f;
    EXPECT_THROW(validate(f), RainParameterError);
    f = SceneFog{};
    f.billboards.strength = std::numeric_limits<float>::quiet_NaN();
    try {
        validate(f);
        ADD_FAILURE() << "no error";
    } catch (const RainParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("billboard strength"), std::string::npos) << e.what();
    }
    f = SceneFog{};
    f.billboards.count = 0;
    EXPECT_THROW(validate(f), RainParameterError);
    EXPECT_THROW(generateFogNoise(2, 16, 1), std::invalid_argument);
}

}  // namespace
}  // namespace prism::rain
