// Extreme inputs of the reference step: never NaN, never negative water, and clear
// errors for inputs it cannot take.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <cmath>
#include <limits>

#include "prism/water/rain_rates.hpp"
#include "prism/water/water_simulation.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

using test::expectFiniteNonNegative;

const double kCloudburst = mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst));

TEST(WaterExtremes, HugeDtSplitsIntoSubsteps) {
    const HeightField terrain = proceduralTerrain({.width = 8, .height = 8, .cellSize = 0.25f, .seed = 2});
    CpuWaterSimulation sim(terrain, proceduralPermeability(terrain), {});
    sim.setRainRate(kCloudburst);
    const SubstepPlan plan = sim.advance(3600.0);  // an hour in one call
    EXPECT_GT(plan.count, 10000);
    EXPECT_LE(plan.dt, maxStableDt(sim.params(), terrain.cellSize) * (1.0 + 1e-12));
    expectFiniteNonNegative(sim, "one hour of cloudburst in one advance()");
    EXPECT_LT(sim.ledger().relativeError(), 1e-6);
}

TEST(WaterExtremes, DtBeyondTheSubstepLimitOrNotFiniteIsAnError) {
    CpuWaterSimulation sim(test::flatTerrain(4, 4), {}, {.maxSubsteps = 1000});
    try {
        sim.advance(1e9);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("maxSubsteps"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sim.advance(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    EXPECT_THROW(sim.advance(-1.0), std::invalid_argument);
    EXPECT_THROW(sim.setRainRate(-1.0), std::invalid_argument);
    EXPECT_THROW(sim.setRainRate(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(WaterExtremes, FlatTerrainStaysUniform) {
    CpuWaterSimulation sim(test::flatTerrain(10, 10, 3.0f), {}, {});
    sim.setRainRate(kCloudburst);
    for (int i = 0; i < 100; ++i) sim.advance(1.0);
    expectFiniteNonNegative(sim, "flat");
    const std::vector<float> d = sim.depth();
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    EXPECT_NEAR(*lo, *hi, 1e-9f) << "no flow on flat ground";
    EXPECT_EQ(sim.ledger().lostThroughBorder, 0.0) << "no slope at the border either";
}

TEST(WaterExtremes, SingleCellPitFills) {
    const HeightField pit = test::pitTerrain(9, 4, 4);
    CpuWaterSimulation sim(pit, {}, {});
    sim.setRainRate(kCloudburst * 20.0);
    for (int i = 0; i < 400; ++i) sim.advance(0.5);
    expectFiniteNonNegative(sim, "pit");
    const std::vector<float> d = sim.depth();
    EXPECT_GT(d[pit.index(4, 4)], 2.0f * d[pit.index(0, 0)]) << "water gathers in the pit";
    EXPECT_LT(sim.ledger().relativeError(), 1e-8);
}

TEST(WaterExtremes, CliffDoesNotBlowUp) {
    const HeightField cliff = test::cliffTerrain(16, 50.0f);  // a 50 m wall
    CpuWaterSimulation sim(cliff, {}, {});
    sim.setRainRate(kCloudburst * 10.0);
    for (int i = 0; i < 300; ++i) sim.advance(0.5);
    expectFiniteNonNegative(sim, "cliff");
    const std::vector<float> d = sim.depth();
    EXPECT_GT(d[cliff.index(7, 8)], d[cliff.index(12, 8)]) << "water runs off the top and gathers at the foot";
    EXPECT_LT(sim.ledger().relativeError(), 1e-8);
}

TEST(WaterExtremes, ZeroAndVeryHighPermeability) {
    const HeightField terrain = proceduralTerrain({.width = 16, .height = 16, .cellSize = 0.25f, .seed = 9});
    CpuWaterSimulation none(terrain, uniformPermeability(terrain, 0.0), {});
    CpuWaterSimulation sponge(terrain, uniformPermeability(terrain, 1e3), {});  // 1 km/s
    for (auto* sim : {&none, &sponge}) {
        sim->setRainRate(kCloudburst);
        for (int i = 0; i < 100; ++i) sim->advance(0.5);
        expectFiniteNonNegative(*sim, "permeability");
        EXPECT_LT(sim->ledger().relativeError(), 1e-8);
    }
    EXPECT_EQ(none.ledger().infiltrated, 0.0);
    EXPECT_EQ(sponge.ledger().stored, 0.0);
}

TEST(WaterExtremes, OneByOneGrid) {
    CpuWaterSimulation sim(test::flatTerrain(1, 1), uniformPermeability(test::flatTerrain(1, 1), 1e-6), {});
    sim.setRainRate(kCloudburst);
    for (int i = 0; i < 100; ++i) sim.advance(10.0);
    expectFiniteNonNegative(sim, "1x1");
    const MassLedger l = sim.ledger();
    EXPECT_NEAR(sim.depth()[0], l.rainIn - l.infiltrated, 1e-9);
    EXPECT_LT(l.relativeError(), 1e-9);
}

TEST(WaterExtremes, Grid2048SingleStep) {
    const auto start = std::chrono::steady_clock::now();
    const HeightField terrain = proceduralTerrain({.width = 2048, .height = 2048, .cellSize = 0.05f, .seed = 1});
    CpuWaterSimulation sim(terrain, {}, {});
    sim.setRainRate(kCloudburst);
    sim.advance(maxStableDt(sim.params(), terrain.cellSize));
    expectFiniteNonNegative(sim, "2048x2048");
    EXPECT_LT(sim.ledger().relativeError(), 1e-9);
    std::cout << "[extremes] 2048x2048: terrain + one CPU step in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
}

TEST(WaterExtremes, BadTerrainAndParametersAreErrors) {
    HeightField empty;
    EXPECT_THROW(CpuWaterSimulation(empty, {}, {}), std::invalid_argument);
    HeightField nan = test::flatTerrain(2, 2);
    nan.heights[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(CpuWaterSimulation(nan, {}, {}), std::invalid_argument);
    EXPECT_THROW(CpuWaterSimulation(test::flatTerrain(2, 2), std::vector<float>(3, 0.0f), {}), std::invalid_argument);
    EXPECT_THROW(CpuWaterSimulation(test::flatTerrain(2, 2), std::vector<float>(4, -1.0f), {}), std::invalid_argument);
    EXPECT_THROW(CpuWaterSimulation(test::flatTerrain(2, 2), {}, {.smoothingKernel = 4}), std::invalid_argument);
    EXPECT_THROW(CpuWaterSimulation(test::flatTerrain(2, 2), {}, {.waveSpeed = 0.0f}), std::invalid_argument);
    CpuWaterSimulation sim(test::flatTerrain(2, 2), {}, {});
    const std::vector<float> negative = {0.0f, -1.0f, 0.0f, 0.0f};
    EXPECT_THROW(sim.setDepth(negative), std::invalid_argument);
}

}  // namespace
}  // namespace prism::water
