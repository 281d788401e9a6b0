// The compute-shader water step against the CPU reference, its mass ledger, and its
// extremes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

#include "prism/water/backend_choice.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/water_scene.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/test/gl_test.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

using WaterGlTest = ::prism::test::GlTest;

// The stated tolerance of CPU/GPU agreement: both run the same fp32 operations in the
// same order, so on a driver that rounds as IEEE 754 (llvmpipe does) they agree to the
// bit; this tolerance leaves room for a driver that fuses a multiply-add.
constexpr float kAgreementAbs = 1e-6f;  // m of water depth
constexpr float kAgreementRel = 1e-4f;  // of the depth

struct Agreement {
    std::size_t identical = 0, cells = 0;
    float maxAbs = 0.0f;
    bool within = true;
};

Agreement compare(const std::vector<glm::vec2>& cpu, const std::vector<glm::vec2>& gpu) {
    Agreement a;
    a.cells = cpu.size();
    for (std::size_t i = 0; i < cpu.size(); ++i) {
        const float c = cpu[i].x + cpu[i].y, g = gpu[i].x + gpu[i].y;
        if (cpu[i] == gpu[i]) ++a.identical;
        const float d = std::abs(c - g);
        a.maxAbs = std::max(a.maxAbs, d);
        if (!(d <= kAgreementAbs + kAgreementRel * std::abs(c))) a.within = false;
    }
    return a;
}

TEST_F(WaterGlTest, GpuAndCpuStepsAgree) {
    const HeightField terrain = proceduralTerrain({.width = 72, .height = 56, .cellSize = 0.25f, .seed = 12});
    const std::vector<float> k = proceduralPermeability(terrain);
    CpuWaterSimulation cpu(terrain, k, {});
    GpuWaterSimulation gpu(terrain, k, {});
    const double rate = mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst)) * 5.0;
    cpu.setRainRate(rate);
    gpu.setRainRate(rate);
    for (int round = 0; round < 2; ++round) {
        for (int i = 0; i < 100; ++i) {
            cpu.advance(0.5);
            gpu.advance(0.5);
        }
        const Agreement depth = compare(cpu.depthPairs(), gpu.depthPairs());
        const Agreement velocity = compare(cpu.edgeVelocities(), gpu.edgeVelocities());
        std::cout << "[agreement] after " << cpu.substepsDone() << " substeps: " << depth.identical << "/"
                  << depth.cells << " depths bit-identical, max |cpu - gpu| = " << depth.maxAbs << " m; velocities "
                  << velocity.identical << "/" << velocity.cells << " identical, max diff " << velocity.maxAbs << "\n";
        EXPECT_TRUE(depth.within) << "max depth difference " << depth.maxAbs;
        EXPECT_LE(velocity.maxAbs, 1e-5f);
    }
    const MassLedger lc = cpu.ledger(), lg = gpu.ledger();
    EXPECT_NEAR(lg.infiltrated, lc.infiltrated, 1e-6 * lc.infiltrated);
    EXPECT_NEAR(lg.lostThroughBorder, lc.lostThroughBorder, 1e-6 * lc.rainIn);
    EXPECT_GT(lc.stored, 0.0);
}

// Agreement over the parameters that change the step's code paths, on grids of several
// 16x16 work groups (64^2 and a 72x80 grid that ends mid-group): closed borders,
// smoothing kernels 1 (off) and 15 (the largest), zero and full permeability (1 mm/s:
// every drop soaks in) and the extreme rain rates (drizzle, and the 10,000 mm/h limit).
struct AgreementCase {
    const char* name;
    int width, height;
    BorderMode border;
    int kernel;
    double permeability;  // m/s, uniform; < 0: the procedural soil map
    double rainMmPerHour;
};

class GpuCpuAgreement : public WaterGlTest, public ::testing::WithParamInterface<AgreementCase> {};

TEST_P(GpuCpuAgreement, DepthsAndVelocitiesMatch) {
    const AgreementCase c = GetParam();
    const HeightField terrain =
        proceduralTerrain({.width = c.width, .height = c.height, .cellSize = 0.25f, .relief = 2.0f, .seed = 21});
    const std::vector<float> k =
        c.permeability < 0.0 ? proceduralPermeability(terrain) : uniformPermeability(terrain, c.permeability);
    WaterParams p;
    p.border = c.border;
    p.smoothingKernel = c.kernel;
    CpuWaterSimulation cpu(terrain, k, p);
    GpuWaterSimulation gpu(terrain, k, p);
    cpu.setRainRate(mmPerHourToMetresPerSecond(c.rainMmPerHour));
    gpu.setRainRate(mmPerHourToMetresPerSecond(c.rainMmPerHour));
    for (int i = 0; i < 30; ++i) {
        cpu.advance(0.5);
        gpu.advance(0.5);
    }
    const Agreement depth = compare(cpu.depthPairs(), gpu.depthPairs());
    const Agreement velocity = compare(cpu.edgeVelocities(), gpu.edgeVelocities());
    std::cout << "[agreement] " << c.name << ": " << depth.identical << "/" << depth.cells
              << " depths bit-identical, max |cpu - gpu| = " << depth.maxAbs << " m; velocities " << velocity.identical
              << "/" << velocity.cells << " identical\n";
    EXPECT_TRUE(depth.within) << "max depth difference " << depth.maxAbs;
    EXPECT_LE(velocity.maxAbs, 1e-5f);
    const MassLedger lc = cpu.ledger(), lg = gpu.ledger();
    EXPECT_NEAR(lg.stored, lc.stored, 1e-6 * std::max(lc.rainIn, 1e-30));
    EXPECT_NEAR(lg.infiltrated, lc.infiltrated, 1e-6 * std::max(lc.rainIn, 1e-30));
    test::expectFiniteNonNegative(gpu, c.name);
}

constexpr double kDrizzleMmPerHour = 0.254, kLimitMmPerHour = kMaxRainMmPerHour;
INSTANTIATE_TEST_SUITE_P(
    Cases, GpuCpuAgreement,
    ::testing::Values(AgreementCase{"closed_k1_dry_soil", 64, 64, BorderMode::Closed, 1, 0.0, 101.6},
                      AgreementCase{"closed_k15_dry_soil", 64, 64, BorderMode::Closed, 15, 0.0, 101.6},
                      AgreementCase{"open_k15_full_permeability", 72, 80, BorderMode::Open, 15, 1e-3, 101.6},
                      AgreementCase{"closed_k5_full_permeability_limit_rain", 64, 64, BorderMode::Closed, 5, 1e-3,
                                    kLimitMmPerHour},
                      AgreementCase{"closed_k1_limit_rain", 72, 80, BorderMode::Closed, 1, 0.0, kLimitMmPerHour},
                      AgreementCase{"open_k15_soil_drizzle", 64, 64, BorderMode::Open, 15, -1.0, kDrizzleMmPerHour},
                      AgreementCase{"closed_k1_soil_drizzle", 72, 80, BorderMode::Closed, 1, -1.0, kDrizzleMmPerHour}),
    [](const ::testing::TestParamInfo<AgreementCase>& info) { return std::string(info.param.name); });

// 10,000 substeps on a 64x64 grid (16 work groups of 16x16). The bound is 10x the
// measured relative error (7.9e-10, printed below).
TEST_F(WaterGlTest, GpuMassLedgerHoldsOver10000Steps) {
    const HeightField terrain =
        proceduralTerrain({.width = 64, .height = 64, .cellSize = 0.25f, .relief = 1.0f, .pits = 2, .seed = 5});
    GpuWaterSimulation gpu(terrain, proceduralPermeability(terrain), {});
    gpu.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Heavy)));
    const double dt = maxStableDt(gpu.params(), terrain.cellSize);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 10000; ++i) gpu.advance(dt);
    const MassLedger l = gpu.ledger();
    std::cout << "[ledger] gpu open 64x64, 10000 steps: relative error " << l.relativeError() << " (stored " << l.stored
              << ", infiltrated " << l.infiltrated << ", lost " << l.lostThroughBorder << " of rain " << l.rainIn
              << " cell-metres) in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s\n";
    EXPECT_LT(l.relativeError(), 7.9e-9);
    test::expectFiniteNonNegative(gpu, "gpu ledger run");
}

// Scenes run whichever step is faster on this renderer, measured once per renderer and
// grid size (prism/water/backend_choice.hpp).
TEST_F(WaterGlTest, TheFastestBackendIsMeasuredOnceAndIsTheFaster) {
    const HeightField terrain = proceduralTerrain({.width = 96, .height = 80, .cellSize = 0.25f, .seed = 3});
    const std::vector<float> k = proceduralPermeability(terrain);
    const BackendChoice first = chooseFastestBackend(terrain, k, {});
    EXPECT_FALSE(first.fromCache);
    EXPECT_GT(first.cpuMsPerSubstep, 0.0);
    ASSERT_GT(first.gpuMsPerSubstep, 0.0) << "the test context has GL 4.3 compute shaders";
    EXPECT_EQ(first.backend,
              first.gpuMsPerSubstep < first.cpuMsPerSubstep ? SimulationBackend::Gpu : SimulationBackend::Cpu);
    std::cout << "[backend] " << first.renderer << " 96x80: cpu " << first.cpuMsPerSubstep << " ms, gpu "
              << first.gpuMsPerSubstep << " ms per substep -> "
              << (first.backend == SimulationBackend::Gpu ? "gpu" : "cpu") << "\n";
    const BackendChoice again = chooseFastestBackend(terrain, k, {});
    EXPECT_TRUE(again.fromCache);
    EXPECT_EQ(again.backend, first.backend);
    EXPECT_EQ(again.cpuMsPerSubstep, first.cpuMsPerSubstep);
    WaterSystem system(terrain, k, {}, SimulationBackend::Fastest, 10.0);
    EXPECT_EQ(system.simulation().backendName(), first.backend == SimulationBackend::Gpu ? "gpu" : "cpu");
}

TEST_F(WaterGlTest, GpuExtremes) {
    // 1x1 grid, huge dt, a cliff and a sponge: finite, non-negative, conserving.
    GpuWaterSimulation one(test::flatTerrain(1, 1), {}, {});
    one.setRainRate(1e-4);
    one.advance(10.0);
    EXPECT_NEAR(one.depth()[0], 1e-3, 1e-9);
    test::expectFiniteNonNegative(one, "gpu 1x1");

    GpuWaterSimulation cliff(test::cliffTerrain(24, 50.0f), {}, {});
    cliff.setRainRate(1e-3);
    const SubstepPlan plan = cliff.advance(100.0);
    EXPECT_GT(plan.count, 200);
    test::expectFiniteNonNegative(cliff, "gpu cliff, huge dt");
    EXPECT_LT(cliff.ledger().relativeError(), 1e-7);

    const HeightField t = proceduralTerrain({.width = 20, .height = 20, .cellSize = 0.25f});
    GpuWaterSimulation sponge(t, uniformPermeability(t, 1e3), {});
    sponge.setRainRate(1e-3);
    sponge.advance(5.0);
    EXPECT_EQ(sponge.ledger().stored, 0.0);
    test::expectFiniteNonNegative(sponge, "gpu sponge");
}

}  // namespace
}  // namespace prism::water
