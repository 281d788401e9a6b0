// Rain intensity for the water system: the six rain classes of RainCL Table 2
// (Bruder 2013, §3.1.2, "Regenformen und -daten", after Lull 1959) mapped to a rain rate, and
// unit conversions. The water simulation itself takes a plain rate (m/s), so a constant
// rain rate works without any class.
//
// Usage (snippet: examples/snippets/water_rain_rates.cpp):
//
//     #include "prism/water/rain_rates.hpp"
//     double mmh = prism::water::rainRateMmPerHour(prism::water::RainClass::Heavy);   // 15.2
//     double ms = prism::water::mmPerHourToMetresPerSecond(mmh);                     // 4.22e-6
//     double r = prism::water::parseRainRateMmPerHour("cloudburst");                 // 101.6
//     double c = prism::water::parseRainRateMmPerHour("12.5");                       // 12.5 (mm/h)
//
// RainCL Table 2 gives the intensity in cm/h; the rates here are those values x 10 (mm/h):
//   drizzle 0.025 cm/h, light 0.102, moderate 1.381, heavy 1.520, excessive 4.064,
//   cloudburst 10.160. (Moderate and heavy are close in the source; kept as printed.)
// The rain engineer's runtime/rain has its own copy of the table; the lead unifies them.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace prism::water {

enum class RainClass { Drizzle, Light, Moderate, Heavy, Excessive, Cloudburst };

struct RainClassInfo {
    RainClass rainClass;
    std::string_view name;        // "drizzle", "light", "moderate", "heavy", "excessive", "cloudburst"
    std::string_view germanName;  // as in RainCL: "Nieselregen", ...
    double intensityCmPerHour;    // Table 2, column "Intensität [cm/h]"
    double dropDiameterMm;        // Table 2, "Menge [mm]" (the drop size)
    double fallSpeedMetresPerSecond;
    double dropsPerSecondPerSquareMetre;
};

// The six rows of RainCL Table 2, drizzle first.
std::span<const RainClassInfo> rainClassTable();
const RainClassInfo& rainClassInfo(RainClass rainClass);

double rainRateMmPerHour(RainClass rainClass);
// Case-insensitive class name ("Heavy", "cloudburst"); nullopt for anything else.
std::optional<RainClass> parseRainClass(std::string_view name);
// A class name, "none" (0) or a non-negative number of mm/h. Throws std::invalid_argument
// naming the text and listing the class names.
double parseRainRateMmPerHour(std::string_view text);

constexpr double mmPerHourToMetresPerSecond(double mmPerHour) {
    return mmPerHour / 1000.0 / 3600.0;
}
constexpr double metresPerSecondToMmPerHour(double metresPerSecond) {
    return metresPerSecond * 3600.0 * 1000.0;
}

}  // namespace prism::water
