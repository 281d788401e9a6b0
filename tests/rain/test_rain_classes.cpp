// The one rain-class table (RainCL Table 2, corrected): every intensity against the
// source's inches per hour, and against the table's own drop columns where they agree.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/rain/rain_classes.hpp"

namespace prism::rain {
namespace {

// Lull 1959, p. 13 (the thesis's [13]), in inches per hour; written out here, not read
// from the table under test.
struct SourceRow {
    RainClass id;
    double inchesPerHour;
};
constexpr SourceRow kSource[] = {
    {RainClass::Drizzle, 0.01}, {RainClass::Light, 0.04},     {RainClass::Moderate, 0.15},
    {RainClass::Heavy, 0.60},   {RainClass::Excessive, 1.60}, {RainClass::Cloudburst, 4.00},
};

TEST(RainClassTable, EveryRowIsItsSourceInchesPerHourTimes2_54) {
    ASSERT_EQ(rainClasses().size(), 6u);
    for (const SourceRow& row : kSource) {
        const RainClassInfo& c = rainClassInfo(row.id);
        const double expectedCm = row.inchesPerHour * 2.54;
        EXPECT_NEAR(c.intensity, expectedCm, 1e-6 * expectedCm) << c.name;
        EXPECT_NEAR(rainRateMmPerHour(row.id), expectedCm * 10.0, 1e-9) << c.name;
    }
    // The thesis's typo: moderate is 0.381 cm/h (0.15 in/h), not the printed 1.381.
    EXPECT_NEAR(rainClassInfo(RainClass::Moderate).intensity, 0.381f, 1e-6f);
    EXPECT_FLOAT_EQ(rainClassInfo(RainClass::Moderate).printedIntensity, 1.381f);
    EXPECT_NEAR(rainClassInfo(RainClass::Heavy).intensity, 1.524f, 1e-6f);
    // Moderate is no longer "almost heavy": heavy is 4x moderate, as 0.60 / 0.15.
    EXPECT_NEAR(rainClassInfo(RainClass::Heavy).intensity / rainClassInfo(RainClass::Moderate).intensity, 4.0f, 1e-5f);
}

// The thesis converts five rows correctly (to its printed precision) and misprints one.
TEST(RainClassTable, ThePrintedIntensityDiffersFromTheSourceOnlyForModerate) {
    for (const RainClassInfo& c : rainClasses()) {
        const double relative = std::abs(c.printedIntensity - c.intensity) / c.intensity;
        if (c.id == RainClass::Moderate)
            EXPECT_GT(relative, 2.0) << "the 1.381 typo";
        else
            EXPECT_LT(relative, 0.02) << c.name;
    }
}

// intensity = drops per m^2 per s x drop volume (pi/6 d^3). The thesis's columns agree
// for drizzle, light and moderate (within 1%); heavy, excessive and cloudburst list about
// half the drops their intensity needs (the source's drop counts are per size class), so
// they are checked to disagree, which keeps the row set of the first check honest.
double intensityFromDropsCmPerHour(const RainClassInfo& c) {
    const double d = c.dropDiameterMm * 1e-3;                        // m
    const double volume = 3.14159265358979323846 / 6.0 * d * d * d;  // m^3 per drop
    return c.dropsPerSquareMetreSecond * volume * 3600.0 * 100.0;    // m/s -> cm/h
}

TEST(RainClassTable, IntensityMatchesDropFluxTimesDropVolumeWhereTheColumnsAgree) {
    for (RainClass id : {RainClass::Drizzle, RainClass::Light, RainClass::Moderate}) {
        const RainClassInfo& c = rainClassInfo(id);
        EXPECT_NEAR(intensityFromDropsCmPerHour(c) / c.intensity, 1.0, 0.05) << c.name;
    }
    // The printed moderate value fails the same check by a factor of 3.6.
    const RainClassInfo& m = rainClassInfo(RainClass::Moderate);
    EXPECT_GT(m.printedIntensity / intensityFromDropsCmPerHour(m), 3.5);
    for (RainClass id : {RainClass::Heavy, RainClass::Excessive, RainClass::Cloudburst}) {
        const RainClassInfo& c = rainClassInfo(id);
        EXPECT_LT(intensityFromDropsCmPerHour(c) / c.intensity, 0.6) << c.name;
    }
}

TEST(RainClassTable, ParsesNamesCaseInsensitively) {
    EXPECT_EQ(parseRainClass("Moderate"), RainClass::Moderate);
    EXPECT_EQ(parseRainClass("CLOUDBURST"), RainClass::Cloudburst);
    EXPECT_FALSE(parseRainClass("monsoon").has_value());
    EXPECT_FALSE(parseRainClass("").has_value());
}

}  // namespace
}  // namespace prism::rain
