// Guard rails of the water API: non-finite or overflowing rain rates, cell sizes, height
// scales and heights are errors that say what is allowed; the substep cap names the
// stability limit c dt / h and the largest dt; heights are kept relative to a local origin
// so the same terrain 3000 m higher gives the same depths.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "prism/water/height_field.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_simulation.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string errorOf(auto&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(WaterGuardRails, RainRateMustBeFiniteAndAtMost10000MillimetresPerHour) {
    CpuWaterSimulation sim(test::flatTerrain(4, 4), {}, {});
    for (double bad : {kInf, kNaN, -1e-9, mmPerHourToMetresPerSecond(1e46), kMaxRainMetresPerSecond * 1.0001})
        EXPECT_THROW(sim.setRainRate(bad), std::invalid_argument) << bad;
    EXPECT_NE(errorOf([&] { sim.setRainRate(mmPerHourToMetresPerSecond(1e46)); }).find("10000 mm/h"),
              std::string::npos);
    sim.setRainRate(kMaxRainMetresPerSecond);  // the limit itself is allowed
    sim.advance(60.0);
    test::expectFiniteNonNegative(sim, "10,000 mm/h for a minute");
    EXPECT_LT(sim.ledger().relativeError(), 1e-9);
}

TEST(WaterGuardRails, TheSubstepCapIsDocumentedAndExplainsTheStabilityLimit) {
    EXPECT_EQ(WaterParams{}.maxSubsteps, kDefaultMaxSubsteps);
    EXPECT_EQ(kDefaultMaxSubsteps, 100'000);
    // A tiny cell size used to ask silently for millions of substeps.
    HeightField tiny = test::flatTerrain(4, 4, 0.0f, 1e-5f);
    CpuWaterSimulation sim(tiny, {}, {});
    const double dtMax = maxStableDt(sim.params(), tiny.cellSize);  // 0.7 * 1e-5 / 0.5 = 1.4e-5 s
    EXPECT_NEAR(dtMax, 1.4e-5, 1e-12);
    const std::string msg = errorOf([&] { sim.advance(20.0); });
    EXPECT_NE(msg.find("c dt / h <= 1/sqrt(2)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("largest stable substep"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.4e-05"), std::string::npos) << "names the largest stable dt: " << msg;
    EXPECT_NE(msg.find("1.4 s"), std::string::npos) << "and the longest call, cap x dtMax: " << msg;
    EXPECT_EQ(sim.substepsDone(), 0) << "nothing ran";
    // The cap is exact: cap x dtMax runs, a little more does not.
    CpuWaterSimulation capped(tiny, {}, {.maxSubsteps = 1000});
    EXPECT_EQ(capped.advance(1000 * dtMax * (1.0 - 1e-9)).count, 1000);
    EXPECT_THROW(capped.advance(1001 * dtMax), std::invalid_argument);
    EXPECT_THROW(capped.advance(kInf), std::invalid_argument);
    EXPECT_THROW(capped.advance(1e300), std::invalid_argument);
}

TEST(WaterGuardRails, CellSizesHeightsAndOriginsMustBeFiniteAndBounded) {
    for (float cell : {0.0f, -1.0f, std::numeric_limits<float>::infinity(), 1e5f}) {
        HeightField f = test::flatTerrain(2, 2);
        f.cellSize = cell;
        EXPECT_THROW(CpuWaterSimulation(f, {}, {}), std::invalid_argument) << cell;
    }
    HeightField high = test::flatTerrain(2, 2);
    high.heights[0] = 2e6f;
    EXPECT_NE(errorOf([&] { CpuWaterSimulation s(high, {}, {}); }).find("HeightField::origin"), std::string::npos);
    HeightField nanOrigin = test::flatTerrain(2, 2);
    nanOrigin.origin = kNaN;
    EXPECT_THROW(CpuWaterSimulation(nanOrigin, {}, {}), std::invalid_argument);
    EXPECT_THROW(maxStableDt(WaterParams{}, std::numeric_limits<float>::infinity()), std::invalid_argument);
}

TEST(WaterGuardRails, HeightMapOptionsMustBeFinite) {
    const auto dir = test::scratchDir("guard-rails");
    writeGreyPng(dir / "map.png", GreyImage{4, 4, 8, std::vector<std::uint16_t>(16, 128)});
    const float inf = std::numeric_limits<float>::infinity();
    for (HeightMapOptions bad : {HeightMapOptions{.heightScale = inf}, HeightMapOptions{.heightScale = 1e7f},
                                 HeightMapOptions{.cellSize = 0.0f}, HeightMapOptions{.cellSize = inf},
                                 HeightMapOptions{.baseHeight = std::numeric_limits<float>::quiet_NaN()}}) {
        const std::string msg = errorOf([&] { loadHeightMap(dir / "map.png", bad); });
        EXPECT_NE(msg.find("map.png"), std::string::npos) << msg;
        EXPECT_NE(msg.find("finite"), std::string::npos) << msg;
    }
}

// Heights on a 2^-10 m grid, so that raising them by 3000 m is exact in fp32 (ulp 2^-12
// there): the two terrains are the same shape, and only the arithmetic can differ.
HeightField quantisedTerrain(float raise) {
    HeightField t = proceduralTerrain({.width = 64, .height = 64, .cellSize = 0.25f, .relief = 3.0f, .seed = 4});
    for (float& h : t.heights) h = std::round(h * 1024.0f) / 1024.0f + raise;
    return t;
}

std::vector<float> depthsAfterRain(const HeightField& terrain) {
    CpuWaterSimulation sim(terrain, uniformPermeability(terrain, 0.0), {});
    sim.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst)) * 20.0);
    for (int i = 0; i < 60; ++i) sim.advance(0.5);
    return sim.depth();
}

TEST(WaterGuardRails, RaisingTheTerrainBy3000MetresChangesNoDepth) {
    const std::vector<float> low = depthsAfterRain(quantisedTerrain(0.0f));
    const std::vector<float> high = depthsAfterRain(quantisedTerrain(3000.0f));
    ASSERT_EQ(low.size(), 4096u);
    int changed = 0;
    float worst = 0.0f;
    for (std::size_t i = 0; i < low.size(); ++i) {
        const float scale = std::max(low[i], 1e-30f);
        const float relative = std::abs(high[i] - low[i]) / scale;
        worst = std::max(worst, relative);
        if (relative > 1e-6f) ++changed;
    }
    EXPECT_EQ(changed, 0) << "cells whose depth changed by more than 1e-6 relative (worst " << worst << ")";
}

TEST(WaterGuardRails, AHeightMapsBaseHeightBecomesItsOrigin) {
    const auto dir = test::scratchDir("origin");
    GreyImage img{16, 16, 16, {}};
    for (int i = 0; i < 256; ++i) img.values.push_back(static_cast<std::uint16_t>((i * 7919) % 65536));
    writeGreyPng(dir / "hills.png", img);
    const HeightField sea = loadHeightMap(dir / "hills.png", {.heightScale = 5.0f, .baseHeight = 0.0f});
    const HeightField alps = loadHeightMap(dir / "hills.png", {.heightScale = 5.0f, .baseHeight = 3000.0f});
    EXPECT_EQ(alps.origin, 3000.0);
    EXPECT_EQ(sea.heights, alps.heights) << "the base height is kept apart from the fp32 heights";
    EXPECT_EQ(depthsAfterRain(sea), depthsAfterRain(alps));
}

}  // namespace
}  // namespace prism::water
