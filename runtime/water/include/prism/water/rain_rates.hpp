// Rain intensity for the water system: the rain classes are prism::rain's one table
// (prism/rain/rain_classes.hpp, RainCL Table 2 with the corrected in/h × 2.54 values),
// forwarded here, plus the parsing of a rain argument and unit conversions. The water
// simulation itself takes a plain rate (m/s), so a constant rain rate works without any class.
//
// Usage (snippet: examples/snippets/water_rain_rates.cpp):
//
//     #include "prism/water/rain_rates.hpp"
//     double mmh = prism::water::rainRateMmPerHour(prism::water::RainClass::Heavy);  // 15.2
//     double ms = prism::water::mmPerHourToMetresPerSecond(mmh);                     // 4.22e-6
//     double r = prism::water::parseRainRateMmPerHour("cloudburst");                 // 101.6
//     double c = prism::water::parseRainRateMmPerHour("12.5");                       // 12.5 (mm/h)
#pragma once

#include <span>
#include <string_view>

#include "prism/rain/rain_classes.hpp"

namespace prism::water {

using rain::parseRainClass;
using rain::RainClass;
using rain::RainClassInfo;
using rain::rainClassInfo;
using rain::rainRateMmPerHour;

// The six rows of Table 2, drizzle first (prism::rain::rainClasses()).
inline std::span<const RainClassInfo> rainClassTable() {
    return rain::rainClasses();
}

// The largest rain rate accepted anywhere in the water system: 10 m/h = 10,000 mm/h,
// about 30 times the heaviest rain ever recorded in an hour (305 mm, Holt, Missouri,
// 1947): room for stress tests, and far from any overflow.
inline constexpr double kMaxRainMmPerHour = 10000.0;

// A class name, "none" (0) or a finite number of mm/h in [0, kMaxRainMmPerHour]. Throws
// std::invalid_argument naming the text and listing the class names.
double parseRainRateMmPerHour(std::string_view text);

constexpr double mmPerHourToMetresPerSecond(double mmPerHour) {
    return mmPerHour / 1000.0 / 3600.0;
}
constexpr double metresPerSecondToMmPerHour(double metresPerSecond) {
    return metresPerSecond * 3600.0 * 1000.0;
}

}  // namespace prism::water
