// The reference water step: the stability bound and substepping, and what each part
// of the step does on terrains with a known answer. Every case also checks the mass
// ledger: each transfer is exact, only the fp32 sum of a cell's transfers in a pass is
// rounded, which leaves ~1e-9 relative per few hundred steps (the 10,000-step ledger
// test is in test_mass_ledger.cpp).
#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "prism/water/rain_rates.hpp"
#include "prism/water/water_simulation.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

using test::bowlTerrain;
using test::flatTerrain;

TEST(WaterStability, SubstepBoundIsCourantTimesCellOverSpeed) {
    WaterParams p;
    p.waveSpeed = 0.5f;
    p.courantNumber = 0.7f;
    EXPECT_NEAR(maxStableDt(p, 0.25f), 0.7 * 0.25 / 0.5, 1e-7);
    p.courantNumber = 0.71f;  // above 1/sqrt(2)
    EXPECT_THROW(validate(p), std::invalid_argument);
    p.courantNumber = 0.7071f;
    EXPECT_NO_THROW(validate(p));
}

TEST(WaterStability, LargeDtSplitsIntoEqualSubstepsWithinTheBound) {
    const WaterParams p;
    const double dtMax = maxStableDt(p, 0.25f);
    const SubstepPlan plan = planSubsteps(10.5 * dtMax, p, 0.25f);
    EXPECT_EQ(plan.count, 11);
    EXPECT_LE(plan.dt, dtMax);
    EXPECT_NEAR(plan.dt * static_cast<double>(plan.count), 10.5 * dtMax, 1e-12);
    EXPECT_LE(static_cast<double>(p.waveSpeed) * plan.dt / 0.25, 1.0 / std::sqrt(2.0));
    EXPECT_EQ(planSubsteps(0.5 * dtMax, p, 0.25f).count, 1);
    EXPECT_EQ(planSubsteps(0.0, p, 0.25f).count, 0);
}

// Mueller's bound, shown on the distribution alone (no rain, flow or smoothing): a
// pool 1 m deep with one raised cell. At c dt / h = 0.70 the wave stays bounded; at
// 0.72 the checkerboard mode grows until the edge caps (a quarter of a cell's water)
// are all that hold it.
double distributionDeviationAfter(float courant, int steps) {
    const HeightField flat = flatTerrain(16, 16, 0.0f, 0.25f);
    WaterParams p;
    p.smoothingKernel = 1;
    p.flowRate = 0.0f;
    p.dampingPerSecond = 0.0f;
    p.epsilon = 1000.0f;  // the plain height-field scheme
    p.border = BorderMode::Closed;
    CpuWaterSimulation sim(flat, {}, p);
    std::vector<float> depth(flat.cellCount(), 1.0f);
    depth[flat.index(8, 8)] = 1.01f;
    sim.setDepth(depth);
    const double dt = courant * flat.cellSize / p.waveSpeed;  // bypasses the checked plan
    sim.advanceWithConstants(stepConstants(p, flat.cellSize, dt, 0.0), steps);
    double worst = 0.0;
    for (float d : sim.depth()) worst = std::max(worst, std::abs(static_cast<double>(d) - 1.0));
    return worst;
}

TEST(WaterStability, DistributionHoldsAt070AndBlowsUpAt072) {
    const double stable = distributionDeviationAfter(0.70f, 3000);
    const double unstable = distributionDeviationAfter(0.72f, 3000);
    std::cout << "[stability] max |depth - 1| after 3000 steps: c dt/h = 0.70 -> " << stable << " m, 0.72 -> "
              << unstable << " m\n";
    EXPECT_LT(stable, 0.011);
    EXPECT_GT(unstable, 0.1);
}

TEST(WaterStep, UniformRainOnFlatClosedGroundRisesEvenly) {
    const HeightField flat = flatTerrain(12, 9);
    WaterParams p;
    p.border = BorderMode::Closed;
    CpuWaterSimulation sim(flat, {}, p);
    const double rate = mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst));
    sim.setRainRate(rate);
    for (int i = 0; i < 200; ++i) sim.advance(0.25);
    const double expected = rate * sim.simulatedTime();
    for (float d : sim.depth()) ASSERT_NEAR(d, expected, expected * 1e-6);
    EXPECT_LT(sim.ledger().relativeError(), 1e-9);
}

TEST(WaterStep, InfiltrationNeverExceedsTheWaterAndNeverGoesNegative) {
    const HeightField flat = flatTerrain(8, 8);
    const double rain = mmPerHourToMetresPerSecond(15.2);
    CpuWaterSimulation sponge(flat, uniformPermeability(flat, 10.0 * rain), {});
    sponge.setRainRate(rain);
    for (int i = 0; i < 50; ++i) sponge.advance(0.3);
    for (float d : sponge.depth()) EXPECT_EQ(d, 0.0f) << "all rain soaks in";
    const MassLedger l = sponge.ledger();
    EXPECT_NEAR(l.infiltrated, l.rainIn, l.rainIn * 1e-6);
    CpuWaterSimulation partial(flat, uniformPermeability(flat, 0.25 * rain), {.border = BorderMode::Closed});
    partial.setRainRate(rain);
    for (int i = 0; i < 50; ++i) partial.advance(0.3);
    const double expected = 0.75 * rain * partial.simulatedTime();
    for (float d : partial.depth()) EXPECT_NEAR(d, expected, expected * 1e-5);
}

TEST(WaterStep, TangentialFlowRunsDownhillAndOffTheOpenBorder) {
    const HeightField slope = test::tiltedTerrain(16, 0.2f);  // falls towards +x
    CpuWaterSimulation sim(slope, {}, {});
    std::vector<float> depth(slope.cellCount(), 0.0f);
    for (int z = 0; z < 16; ++z) depth[slope.index(2, z)] = 0.01f;  // a strip near the top
    sim.setDepth(depth);
    for (int i = 0; i < 40; ++i) sim.advance(0.25);
    const std::vector<float> after = sim.depth();
    double centreOfMass = 0.0, mass = 0.0;
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) {
            centreOfMass += x * static_cast<double>(after[slope.index(x, z)]);
            mass += after[slope.index(x, z)];
        }
    const MassLedger l = sim.ledger();
    EXPECT_GT(l.lostThroughBorder, 0.0) << "water reached the low edge and left";
    if (mass > 0.0) {
        EXPECT_GT(centreOfMass / mass, 2.5) << "the water moved downhill";
    }
    EXPECT_LT(l.relativeError(), 1e-7);
}

TEST(WaterStep, ClosedBorderKeepsEverything) {
    const HeightField slope = test::tiltedTerrain(16, 0.2f);
    CpuWaterSimulation sim(slope, {}, {.border = BorderMode::Closed});
    sim.setRainRate(mmPerHourToMetresPerSecond(40.0));
    for (int i = 0; i < 100; ++i) sim.advance(0.25);
    const MassLedger l = sim.ledger();
    EXPECT_EQ(l.lostThroughBorder, 0.0);
    EXPECT_LT(l.relativeError(), 1e-9);
    const std::vector<float> d = sim.depth();
    EXPECT_GT(d[slope.index(15, 8)], 10.0f * d[slope.index(0, 8)]) << "collects at the low wall";
}

TEST(WaterStep, BowlCollectsAPuddleWithALevelSurface) {
    const HeightField bowl = bowlTerrain(24, 0.4f);
    CpuWaterSimulation sim(bowl, {}, {});
    sim.setRainRate(mmPerHourToMetresPerSecond(400.0));
    for (int i = 0; i < 300; ++i) sim.advance(0.5);
    sim.setRainRate(0.0);
    for (int i = 0; i < 300; ++i) sim.advance(0.5);  // let it settle
    const std::vector<float> d = sim.depth();
    const float centre = d[bowl.index(12, 12)];
    EXPECT_GT(centre, 0.01f) << "a puddle in the middle";
    // The puddle's surface is level: surface heights of cells deeper than 5 mm agree.
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t i = 0; i < d.size(); ++i)
        if (d[i] > 0.005f) {
            lo = std::min(lo, bowl.heights[i] + d[i]);
            hi = std::max(hi, bowl.heights[i] + d[i]);
        }
    EXPECT_LT(hi - lo, 0.01f) << "surface spread " << (hi - lo) << " m";
    EXPECT_LT(sim.ledger().relativeError(), 1e-7);
}

// Algorithm 1 of RainCL (§4.2.4): a neighbour takes part in the distribution when its
// surface is lower than the cell's own or within epsilon above it. Two scenes on a strip
// (3 rows, closed border, distribution only): a pool at 0 m, 0.2 m deep with a 1 cm crest
// over its last 4 of 12 columns, next to a flat bank whose top is `bank` m high.
struct BankScene {
    HeightField terrain;
    std::vector<float> depth;
};

BankScene bankScene(float bank, float crest) {
    BankScene s{flatTerrain(24, 3, 0.0f), std::vector<float>(72, 0.0f)};
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 24; ++x) {
            if (x >= 12)
                s.terrain.heights[s.terrain.index(x, z)] = bank;
            else
                s.depth[s.terrain.index(x, z)] = 0.2f + (x >= 8 ? crest : 0.0f);
        }
    return s;
}

WaterParams distributionOnly(float epsilon) {
    WaterParams p;
    p.border = BorderMode::Closed;
    p.flowRate = 0.0f;
    p.smoothingKernel = 1;
    p.dampingPerSecond = 0.5f;
    p.epsilon = epsilon;
    return p;
}

// The pool's level clears the bank by less than epsilon: the mass gives a level surface
// L = 0.20192 m over pool and bank, 1.4 mm above the bank top (epsilon = 2 mm). Within
// 20 s the water spreads over the bank to that level. With epsilon = 0 every momentum
// step that meets a bank film a hair higher is cut, and after 20 s the bank holds only
// 87% of its share (checked by hand: fails with epsilon = 0).
TEST(WaterStep, EpsilonLetsALevelThatClearsABankByLessThanEpsilonSpreadOverIt) {
    const float bank = 0.2005f;
    const BankScene s = bankScene(bank, 0.01f);
    const WaterParams p = distributionOnly(WaterParams{}.epsilon);
    ASSERT_GT(p.epsilon, 0.0f);
    CpuWaterSimulation sim(s.terrain, {}, p);
    sim.setDepth(s.depth);
    for (int i = 0; i < 400; ++i) sim.advance(0.05);
    // Level surface from the mass: 12 L + 12 (L - bank) = pool water per row.
    const double perRow = 12 * 0.2 + 4 * 0.01;
    const double level = (perRow + 12.0 * bank) / 24.0;
    ASSERT_LT(level - bank, p.epsilon) << "the scene must clear the bank by less than epsilon";
    const double expectedOnBank = 3 * 12 * (level - bank);
    const std::vector<float> d = sim.depth();
    double onBank = 0.0;
    for (int z = 0; z < 3; ++z)
        for (int x = 12; x < 24; ++x) onBank += d[s.terrain.index(x, z)];
    EXPECT_NEAR(onBank / expectedOnBank, 1.0, 0.05) << onBank << " of " << expectedOnBank << " m on the bank";
    EXPECT_LT(sim.ledger().relativeError(), 1e-9);
}

// A 3 cm crest runs at a bank 1 cm above the pool's resting surface: it clears the bank,
// and as it falls back, momentum would keep pushing water onto the now higher bank film.
// The rule stops every transfer to a neighbour standing epsilon or more above the giver:
// checked substep by substep from the surfaces before and the edge velocities after
// (fails with the rule deleted, i.e. epsilon = 1e9).
TEST(WaterStep, EpsilonRuleKeepsMomentumFromCarryingWaterUpABank) {
    const BankScene s = bankScene(0.21f, 0.03f);
    const WaterParams p = distributionOnly(WaterParams{}.epsilon);
    CpuWaterSimulation sim(s.terrain, {}, p);
    sim.setDepth(s.depth);
    const double dt = maxStableDt(p, s.terrain.cellSize);
    int uphill = 0, transfersOntoTheBank = 0;
    for (int step = 0; step < 600; ++step) {
        const std::vector<float> before = sim.depth();
        ASSERT_EQ(sim.advance(dt).count, 1);
        const std::vector<glm::vec2> q = sim.edgeVelocities();
        for (int z = 0; z < 3; ++z)
            for (int x = 0; x + 1 < 24; ++x) {
                const std::size_t i = s.terrain.index(x, z), j = i + 1;
                const float si = s.terrain.heights[i] + before[i], sj = s.terrain.heights[j] + before[j];
                if (x == 11 && q[i].x > 0.0f) ++transfersOntoTheBank;
                if ((q[i].x > 0.0f && sj >= si + p.epsilon) || (q[i].x < 0.0f && si >= sj + p.epsilon)) ++uphill;
            }
    }
    EXPECT_GT(transfersOntoTheBank, 10) << "the crest must reach the bank";
    EXPECT_EQ(uphill, 0) << "transfers to a neighbour standing epsilon or more above the giver";
    EXPECT_LT(sim.ledger().relativeError(), 1e-9);
}

TEST(WaterStep, GaussianKernelIsNormalisedAndSmoothingConservesMass) {
    for (int kernel : {3, 5, 9, 15}) {
        const std::vector<double> g = gaussianWeights(kernel, 1.5f);
        double sum = g[0];
        for (std::size_t k = 1; k < g.size(); ++k) sum += 2.0 * g[k];
        EXPECT_NEAR(sum, 1.0, 1e-15) << kernel;
    }
    // Smoothing alone on a noisy pool: the variance falls, the mass stays.
    const HeightField flat = flatTerrain(20, 20);
    WaterParams p;
    p.flowRate = 0.0f;
    p.waveSpeed = 1e-6f;  // no distribution to speak of
    p.smoothingKernel = 7;
    p.smoothingRate = 5.0f;
    p.border = BorderMode::Closed;
    p.maxSubsteps = 100000000;
    CpuWaterSimulation sim(flat, {}, p);
    std::vector<float> depth(flat.cellCount());
    for (std::size_t i = 0; i < depth.size(); ++i)
        depth[i] = 0.05f + 0.04f * static_cast<float>((i * 7919) % 13) / 13.0f;
    sim.setDepth(depth);
    auto variance = [](const std::vector<float>& v) {
        const double m = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
        double s = 0.0;
        for (float x : v) s += (x - m) * (x - m);
        return s / static_cast<double>(v.size());
    };
    const double before = variance(sim.depth());
    for (int i = 0; i < 20; ++i) sim.advance(0.05);
    EXPECT_LT(variance(sim.depth()), 0.1 * before);
    EXPECT_LT(sim.ledger().relativeError(), 1e-7);
}

}  // namespace
}  // namespace prism::water
