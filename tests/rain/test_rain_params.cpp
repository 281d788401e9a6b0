// Rain parameters: RainCL Table 2, the rate interpolation, the particle-count
// formula (docs/rain.md) with its budget, and clear errors for bad parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_simulation.hpp"

namespace prism::rain {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(RainClasses, AreTheSixRowsOfTable2) {
    const auto classes = rainClasses();
    ASSERT_EQ(classes.size(), 6u);
    EXPECT_EQ(classes.front().name, "drizzle");
    EXPECT_EQ(classes.back().name, "cloudburst");
    EXPECT_FLOAT_EQ(classes.front().fallSpeed, 4.1f);
    EXPECT_FLOAT_EQ(classes.back().fallSpeed, 7.9f);
    EXPECT_FLOAT_EQ(rainClassInfo(RainClass::Moderate).dropsPerSquareMetreSecond, 495.0f);
    EXPECT_FLOAT_EQ(rainClassInfo(RainClass::Cloudburst).dropsPerSquareMetreSecond, 1216.0f);
    EXPECT_FLOAT_EQ(rainClassInfo(RainClass::Excessive).intensity, 4.064f);
    for (std::size_t i = 1; i < classes.size(); ++i) {
        EXPECT_GT(classes[i].intensity, classes[i - 1].intensity);
        EXPECT_GT(classes[i].fallSpeed, classes[i - 1].fallSpeed);
        EXPECT_GE(classes[i].dropsPerSquareMetreSecond, classes[i - 1].dropsPerSquareMetreSecond);
    }
}

TEST(RainClasses, ParseByNameCaseInsensitive) {
    EXPECT_EQ(parseRainClass("Heavy"), RainClass::Heavy);
    EXPECT_EQ(parseRainClass("cloudburst"), RainClass::Cloudburst);
    EXPECT_FALSE(parseRainClass("monsoon").has_value());
    EXPECT_EQ(nearestRainClass(0.4f), RainClass::Moderate);
    EXPECT_EQ(nearestRainClass(1.4f), RainClass::Heavy);
    EXPECT_EQ(nearestRainClass(50.0f), RainClass::Cloudburst);
}

TEST(RainRate, HitsEveryTableRowExactly) {
    for (const auto& c : rainClasses()) {
        const RainRate r = rainRateFor(c.intensity);
        EXPECT_NEAR(r.fallSpeed, c.fallSpeed, 1e-4f) << c.name;
        EXPECT_NEAR(r.dropsPerSquareMetreSecond, c.dropsPerSquareMetreSecond, 1e-2f) << c.name;
    }
}

TEST(RainRate, IsMonotoneAndZeroWithoutRain) {
    EXPECT_EQ(rainRateFor(0.0f).dropsPerSquareMetreSecond, 0.0f);
    EXPECT_GT(rainRateFor(0.0f).fallSpeed, 0.0f);  // never a division by zero
    RainRate previous = rainRateFor(0.001f);
    for (float i = 0.001f; i < 40.0f; i *= 1.07f) {
        const RainRate r = rainRateFor(i);
        EXPECT_GE(r.fallSpeed, previous.fallSpeed - 1e-5f) << i;
        EXPECT_GE(r.dropsPerSquareMetreSecond, previous.dropsPerSquareMetreSecond - 1e-3f) << i;
        EXPECT_GE(r.fallSpeed, 4.1f - 1e-5f);
        EXPECT_LE(r.fallSpeed, 7.9f + 1e-5f);
        previous = r;
    }
    // Beyond a cloudburst the flux grows in proportion, the speed stays terminal.
    EXPECT_NEAR(rainRateFor(20.32f).dropsPerSquareMetreSecond, 2432.0f, 0.5f);
}

TEST(ParticleCount, FollowsTheDocumentedFormula) {
    RainParams p;
    p.budget = kMaxParticles;
    for (const auto& c : rainClasses()) {
        p.intensity = c.intensity;
        const double area = lodWeightedArea(p.radius, p.lodRings, p.lodFalloff);
        const double expected = p.particlesPerDrop * (c.dropsPerSquareMetreSecond / c.fallSpeed) * p.height * area;
        EXPECT_NEAR(particleCountFor(p), expected, 0.5 + 1e-4 * expected) << c.name;
    }
    // Moderate rain in the default 25 m x 20 m cylinder: 86.8 drops/m^3, V_LOD = 11,352 m^3.
    p.intensity = rainClassInfo(RainClass::Moderate).intensity;
    EXPECT_NEAR(particleCountFor(p), 49290.0, 10.0);
}

TEST(ParticleCount, LodAreaIsTheDiscWithoutFalloff) {
    EXPECT_NEAR(lodWeightedArea(10.0f, 4, 1.0f), 3.14159265 * 100.0, 1e-6);
    EXPECT_NEAR(lodWeightedArea(10.0f, 1, 0.5f), 3.14159265 * 100.0, 1e-6);
    // Ring k has area pi (R/K)^2 (2k + 1) and weight falloff^k.
    EXPECT_NEAR(lodWeightedArea(4.0f, 2, 0.5f), 3.14159265 * 4.0 * (1.0 + 0.5 * 3.0), 1e-6);
}

TEST(ParticleCount, GrowsWithIntensityWhereTheTableDensityGrows) {
    RainParams p;
    p.budget = kMaxParticles;
    const RainClass order[] = {RainClass::Drizzle, RainClass::Light, RainClass::Moderate, RainClass::Excessive,
                               RainClass::Cloudburst};
    std::uint32_t previous = 0;
    for (RainClass c : order) {
        p.intensity = rainClassInfo(c).intensity;
        const std::uint32_t n = particleCountFor(p);
        EXPECT_GT(n, previous) << rainClassInfo(c).name;
        previous = n;
    }
    // Heavy rain has moderate rain's flux (495) at a higher speed (6.7 vs 5.7 m/s), so the
    // air holds fewer drops: the count is physical, N / v, not a guess (docs/rain.md).
    p.intensity = rainClassInfo(RainClass::Heavy).intensity;
    const std::uint32_t heavy = particleCountFor(p);
    p.intensity = rainClassInfo(RainClass::Moderate).intensity;
    EXPECT_NEAR(static_cast<double>(heavy) / particleCountFor(p), 5.7 / 6.7, 1e-3);
}

TEST(ParticleCount, ScalesWithTheCylinderVolume) {
    RainParams p;
    p.budget = kMaxParticles;
    const double base = particleCountFor(p);
    RainParams taller = p;
    taller.height *= 2.0f;
    taller.below *= 2.0f;
    EXPECT_NEAR(particleCountFor(taller) / base, 2.0, 1e-3);
    RainParams wider = p;
    wider.radius *= 2.0f;
    EXPECT_NEAR(particleCountFor(wider) / base, 4.0, 1e-3);
}

TEST(ParticleCount, BudgetCapsAndZeroIntensityIsEmpty) {
    RainParams p;
    p.intensity = rainClassInfo(RainClass::Cloudburst).intensity;
    p.budget = 1000;
    EXPECT_EQ(particleCountFor(p), 1000u);
    p.budget = 0;
    EXPECT_EQ(particleCountFor(p), 0u);
    p.budget = 1u << 18;
    p.intensity = 0.0f;
    EXPECT_EQ(particleCountFor(p), 0u);
    p.fixedCount = 12345u;  // benchmarks: a fixed count, whatever the intensity
    EXPECT_EQ(particleCountFor(p), 12345u);
}

// Expects RainParameterError whose message contains every fragment.
template <class F>
void expectError(F&& f, std::initializer_list<const char*> fragments) {
    try {
        f();
        ADD_FAILURE() << "no RainParameterError";
    } catch (const RainParameterError& e) {
        const std::string m = e.what();
        for (const char* frag : fragments)
            EXPECT_NE(m.find(frag), std::string::npos) << "'" << frag << "' not in: " << m;
    }
}

TEST(RainParamsValidation, BadParametersGiveClearErrors) {
    auto with = [](auto change) {
        RainParams p;
        change(p);
        return p;
    };
    expectError([&] { validate(with([](RainParams& p) { p.intensity = -1.0f; })); }, {"intensity", ">= 0", "-1"});
    expectError([&] { validate(with([](RainParams& p) { p.intensity = kNaN; })); }, {"intensity", "nan"});
    expectError([&] { validate(with([](RainParams& p) { p.intensity = kInf; })); }, {"intensity", "inf"});
    expectError([&] { validate(with([](RainParams& p) { p.wind.strength = kNaN; })); }, {"wind strength", "nan"});
    expectError([&] { validate(with([](RainParams& p) { p.wind.strength = -3.0f; })); }, {"wind strength", "-3"});
    expectError([&] { validate(with([](RainParams& p) { p.wind.directionDegrees = kNaN; })); }, {"wind direction"});
    expectError([&] { validate(with([](RainParams& p) { p.radius = 0.0f; })); }, {"radius"});
    expectError([&] { validate(with([](RainParams& p) { p.height = kInf; })); }, {"height"});
    expectError([&] { validate(with([](RainParams& p) { p.below = 30.0f; })); }, {"below", "height"});
    expectError([&] { validate(with([](RainParams& p) { p.lodRings = 0; })); }, {"lodRings"});
    expectError([&] { validate(with([](RainParams& p) { p.lodFalloff = 0.0f; })); }, {"lodFalloff"});
    expectError([&] { validate(with([](RainParams& p) { p.particlesPerDrop = 2.0f; })); }, {"particlesPerDrop"});
    expectError([&] { validate(with([](RainParams& p) { p.budget = kMaxParticles + 1; })); }, {"budget", "2^24"});
    expectError([&] { validate(with([](RainParams& p) { p.fixedCount = kMaxParticles + 1; })); }, {"fixedCount"});
    expectError([&] { validate(with([](RainParams& p) { p.jitter = -0.1f; })); }, {"jitter"});
    expectError([&] { validate(with([](RainParams& p) { p.streaks.exposure = 0.0f; })); }, {"exposure"});
    expectError([&] { validate(with([](RainParams& p) { p.streaks.opacity = kNaN; })); }, {"opacity"});
    expectError([] { (void)rainRateFor(-0.5f); }, {"intensity"});
    expectError([] { (void)clampStep(-1.0f); }, {"time step", "-1"});
    expectError([] { (void)clampStep(kNaN); }, {"time step"});
    expectError([] { validateEye({0.0f, kNaN, 0.0f}); }, {"camera position", "nan"});
    // Every error is also a std::invalid_argument.
    EXPECT_THROW(validate(with([](RainParams& p) { p.intensity = -1.0f; })), std::invalid_argument);
    EXPECT_NO_THROW(validate(RainParams{}));
}

TEST(Wind, DirectionRandomFromTheSeedOrGiven) {
    RainParams a;
    a.wind.strength = 5.0f;
    RainParams b = a;
    b.seed = a.seed + 1;
    const glm::vec3 wa = windVector(a), wb = windVector(b);
    EXPECT_NEAR(std::hypot(wa.x, wa.z), 5.0f, 1e-5f);
    EXPECT_EQ(wa.y, 0.0f);
    EXPECT_EQ(windVector(a), wa);  // deterministic for a seed
    EXPECT_NE(wa, wb);             // random across seeds
    a.wind.directionDegrees = 90.0f;
    const glm::vec3 w = windVector(a);
    EXPECT_NEAR(w.x, 0.0f, 1e-5f);
    EXPECT_NEAR(w.z, 5.0f, 1e-5f);
    a.wind.strength = 0.0f;
    EXPECT_EQ(windVector(a), glm::vec3(0.0f));
}

TEST(Step, IsClampedToTheMaximum) {
    EXPECT_EQ(clampStep(0.0f), 0.0f);
    EXPECT_EQ(clampStep(0.016f), 0.016f);
    EXPECT_EQ(clampStep(1e9f), kMaxStepSeconds);
    EXPECT_EQ(clampStep(kInf), kMaxStepSeconds);
}

}  // namespace
}  // namespace prism::rain
