// The rain classes of RainCL Table 2 and their parsing (see rain_rates.hpp).
#include "prism/water/rain_rates.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace prism::water {
namespace {

constexpr std::array<RainClassInfo, 6> kTable = {{
    {RainClass::Drizzle, "drizzle", "Nieselregen", 0.025, 0.96, 4.1, 151},
    {RainClass::Light, "light", "Leichter Regen", 0.102, 1.24, 4.8, 280},
    {RainClass::Moderate, "moderate", "M\xC3\xA4\xC3\x9Figer Regen", 1.381, 1.60, 5.7, 495},
    {RainClass::Heavy, "heavy", "Starkregen", 1.520, 2.05, 6.7, 495},
    {RainClass::Excessive, "excessive", "Exzessiver Regen", 4.064, 2.40, 7.3, 818},
    {RainClass::Cloudburst, "cloudburst", "Wolkenbruch", 10.160, 2.85, 7.9, 1216},
}};

std::string lower(std::string_view s) {
    std::string out;
    for (char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::span<const RainClassInfo> rainClassTable() {
    return kTable;
}

const RainClassInfo& rainClassInfo(RainClass rainClass) {
    for (const auto& row : kTable)
        if (row.rainClass == rainClass) return row;
    throw std::invalid_argument("prism::water: unknown rain class");
}

double rainRateMmPerHour(RainClass rainClass) {
    return rainClassInfo(rainClass).intensityCmPerHour * 10.0;
}

std::optional<RainClass> parseRainClass(std::string_view name) {
    const std::string l = lower(name);
    for (const auto& row : kTable)
        if (l == row.name) return row.rainClass;
    return std::nullopt;
}

double parseRainRateMmPerHour(std::string_view text) {
    if (auto c = parseRainClass(text)) return rainRateMmPerHour(*c);
    if (lower(text) == "none") return 0.0;
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc() && ptr == end && std::isfinite(value) && value >= 0.0) return value;
    std::string names;
    for (const auto& row : kTable) names += std::string(names.empty() ? "" : ", ") + std::string(row.name);
    throw std::invalid_argument("rain '" + std::string(text) + "' is neither a rain class (" + names +
                                ", none) nor a number of mm/h >= 0");
}

}  // namespace prism::water
