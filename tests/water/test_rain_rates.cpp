// The water system's rain argument: the shared class table (prism/rain/rain_classes.hpp,
// corrected Table 2) in mm/h, names, numbers, "none", and bad input.
#include <gtest/gtest.h>

#include <stdexcept>

#include "prism/water/procedural_textures.hpp"
#include "prism/water/rain_rates.hpp"

namespace prism::water {
namespace {

TEST(RainRates, ClassesInMillimetresPerHourAreTheSourceInchesPerHourTimes25_4) {
    // Lull 1959 (RainCL's source for Table 2): 0.01, 0.04, 0.15, 0.60, 1.60, 4.00 in/h.
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Drizzle), 0.254, 1e-12);
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Light), 1.016, 1e-12);
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Moderate), 3.81, 1e-12);  // the thesis prints 1.381 cm/h
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Heavy), 15.24, 1e-12);
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Excessive), 40.64, 1e-12);
    EXPECT_NEAR(rainRateMmPerHour(RainClass::Cloudburst), 101.6, 1e-12);
    EXPECT_EQ(rainClassTable().size(), 6u);
    EXPECT_EQ(rainClassTable().data(), rain::rainClasses().data()) << "one table, shared with prism::rain";
}

TEST(RainRates, ParsesClassNamesNumbersAndNone) {
    EXPECT_EQ(parseRainClass("Cloudburst"), RainClass::Cloudburst);
    EXPECT_EQ(parseRainClass("drizzle"), RainClass::Drizzle);
    EXPECT_FALSE(parseRainClass("monsoon").has_value());
    EXPECT_NEAR(parseRainRateMmPerHour("heavy"), 15.24, 1e-12);
    EXPECT_DOUBLE_EQ(parseRainRateMmPerHour("12.5"), 12.5);
    EXPECT_DOUBLE_EQ(parseRainRateMmPerHour("none"), 0.0);
    try {
        parseRainRateMmPerHour("monsoon");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("monsoon"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("cloudburst"), std::string::npos) << "lists the class names";
    }
    EXPECT_THROW(parseRainRateMmPerHour("-3"), std::invalid_argument);
}

TEST(RainRates, RejectsNonFiniteAndOverflowingRates) {
    for (const char* bad : {"1e46", "inf", "nan", "1e309", "10000.5"})
        EXPECT_THROW(parseRainRateMmPerHour(bad), std::invalid_argument) << bad;
    EXPECT_DOUBLE_EQ(parseRainRateMmPerHour("10000"), kMaxRainMmPerHour);
}

// The ripple layers grow with the rain class: more drops per m^2 and s, more rings.
TEST(RainRates, RippleDensityFollowsTheRainIntensity) {
    EXPECT_EQ(rippleDensity(0.0), 0.0f);
    float previous = 0.0f;
    for (const auto& row : rainClassTable()) {
        const float density = rippleDensity(rainRateMmPerHour(row.id));
        EXPECT_GE(density, previous) << row.name;
        EXPECT_GE(density, 0.5f);
        EXPECT_LE(density, 4.0f);
        previous = density;
    }
    EXPECT_GT(rippleDensity(rainRateMmPerHour(RainClass::Cloudburst)),
              2.0f * rippleDensity(rainRateMmPerHour(RainClass::Light)));
}

TEST(RainRates, UnitConversions) {
    EXPECT_DOUBLE_EQ(mmPerHourToMetresPerSecond(3600.0), 1e-3);
    EXPECT_DOUBLE_EQ(metresPerSecondToMmPerHour(mmPerHourToMetresPerSecond(15.2)), 15.2);
}

}  // namespace
}  // namespace prism::water
