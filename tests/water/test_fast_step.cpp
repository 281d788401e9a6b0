// The fast CPU step (passes fused row by row, row bands on threads with halo rows,
// vectorised interior sweeps) against the first single-threaded per-pass, per-cell step:
// the depths and edge velocities are bit-identical for every thread count tried (1 to 16:
// bands from the whole grid to 8 rows, thinner than the halo of kernel 15), odd grid
// shapes, border,
// smoothing kernel and permeability tried, and the ledger's sums (per row, then over
// rows) agree within 1e-12 relative.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "prism/water/rain_rates.hpp"
#include "prism/water/water_simulation.hpp"
#include "reference_water_step.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

struct Case {
    int width, height;
    BorderMode border;
    int kernel;
    double permeabilityMmPerHour;
    double rainMultiple;  // x cloudburst
};

bool sameBits(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec2)) == 0;
}

std::string name(const Case& c, int threads) {
    return std::to_string(c.width) + "x" + std::to_string(c.height) +
           (c.border == BorderMode::Open ? " open" : " closed") + " kernel " + std::to_string(c.kernel) +
           " permeability " + std::to_string(c.permeabilityMmPerHour) + " threads " + std::to_string(threads);
}

TEST(FastCpuStep, IsBitIdenticalToTheFirstStepForEveryThreadCount) {
    const Case cases[] = {
        {160, 130, BorderMode::Open, 5, 6.0, 20.0}, {131, 140, BorderMode::Closed, 15, 0.0, 20.0},
        {144, 129, BorderMode::Open, 1, 1e4, 1.0},  {200, 128, BorderMode::Closed, 3, 12.0, 50.0},
        {9, 300, BorderMode::Open, 15, 6.0, 20.0},  {300, 3, BorderMode::Closed, 5, 6.0, 20.0},
        {129, 131, BorderMode::Open, 7, 6.0, 20.0}, {128, 129, BorderMode::Open, 15, 3.0, 50.0},
    };
    for (const Case& c : cases) {
        const HeightField terrain =
            proceduralTerrain({.width = c.width, .height = c.height, .cellSize = 0.25f, .relief = 3.0f, .seed = 5});
        PermeabilityOptions soil;
        soil.soilMmPerHour = c.permeabilityMmPerHour;
        soil.clayMmPerHour = std::min(soil.clayMmPerHour, c.permeabilityMmPerHour);
        const std::vector<float> k = proceduralPermeability(terrain, soil);
        const double rain = mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst)) * c.rainMultiple;
        WaterParams p;
        p.border = c.border;
        p.smoothingKernel = c.kernel;
        test::ReferenceWaterSimulation reference(terrain, k, p);
        reference.setRainRate(rain);
        for (int i = 0; i < 12; ++i) reference.advance(1.0);
        for (int threads : {1, 2, 3, 7, 16}) {
            p.threads = threads;
            CpuWaterSimulation fast(terrain, k, p);
            fast.setRainRate(rain);
            for (int i = 0; i < 12; ++i) fast.advance(1.0);
            EXPECT_TRUE(sameBits(fast.depthPairs(), reference.depthPairs())) << name(c, threads);
            EXPECT_TRUE(sameBits(fast.edgeVelocities(), reference.edgeVelocities())) << name(c, threads);
            const MassLedger a = fast.ledger(), b = reference.ledger();
            EXPECT_NEAR(a.infiltrated, b.infiltrated, 1e-12 * std::max(1e-30, b.infiltrated)) << name(c, threads);
            EXPECT_NEAR(a.lostThroughBorder, b.lostThroughBorder, 1e-12 * std::max(1e-30, b.lostThroughBorder))
                << name(c, threads);
            EXPECT_EQ(a.stored, b.stored) << name(c, threads);
        }
    }
}

TEST(FastCpuStep, UsesTheRequestedThreadsOnLargeGridsAndOneOnSmallOnes) {
    const HeightField big = test::flatTerrain(256, 256);
    EXPECT_EQ(CpuWaterSimulation(big, {}, {.threads = 2}).threads(), 2);
    EXPECT_GE(CpuWaterSimulation(big, {}, {}).threads(), 1);
    EXPECT_EQ(CpuWaterSimulation(test::flatTerrain(64, 64), {}, {.threads = 4}).threads(), 1);
    EXPECT_THROW(CpuWaterSimulation(big, {}, {.threads = -1}), std::invalid_argument);
    EXPECT_THROW(CpuWaterSimulation(big, {}, {.threads = 65}), std::invalid_argument);
}

}  // namespace
}  // namespace prism::water
