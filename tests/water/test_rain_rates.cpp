// The rain classes of RainCL Table 2 as rain rates for the water system.
#include <gtest/gtest.h>

#include <stdexcept>

#include "prism/water/rain_rates.hpp"

namespace prism::water {
namespace {

TEST(RainRates, TableTwoIntensitiesInMillimetresPerHour) {
    // RainCL Table 2, "Intensität [cm/h]", x 10.
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Drizzle), 0.25);
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Light), 1.02);
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Moderate), 13.81);
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Heavy), 15.2);
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Excessive), 40.64);
    EXPECT_DOUBLE_EQ(rainRateMmPerHour(RainClass::Cloudburst), 101.6);
    EXPECT_EQ(rainClassTable().size(), 6u);
    EXPECT_EQ(rainClassInfo(RainClass::Cloudburst).dropsPerSecondPerSquareMetre, 1216);
}

TEST(RainRates, ParsesClassNamesNumbersAndNone) {
    EXPECT_EQ(parseRainClass("Cloudburst"), RainClass::Cloudburst);
    EXPECT_EQ(parseRainClass("drizzle"), RainClass::Drizzle);
    EXPECT_FALSE(parseRainClass("monsoon").has_value());
    EXPECT_DOUBLE_EQ(parseRainRateMmPerHour("heavy"), 15.2);
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

TEST(RainRates, UnitConversions) {
    EXPECT_DOUBLE_EQ(mmPerHourToMetresPerSecond(3600.0), 1e-3);
    EXPECT_DOUBLE_EQ(metresPerSecondToMmPerHour(mmPerHourToMetresPerSecond(15.2)), 15.2);
}

}  // namespace
}  // namespace prism::water
