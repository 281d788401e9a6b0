// Parsing of a rain argument for the water system (see rain_rates.hpp); the classes
// themselves are prism::rain's table.
#include "prism/water/rain_rates.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace prism::water {

double parseRainRateMmPerHour(std::string_view text) {
    if (auto c = parseRainClass(text)) return rainRateMmPerHour(*c);
    std::string lower;
    for (char ch : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower == "none") return 0.0;
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc() && ptr == end && std::isfinite(value) && value >= 0.0 && value <= kMaxRainMmPerHour)
        return value;
    throw std::invalid_argument("rain '" + std::string(text) + "' is neither a rain class (" + rain::rainClassNames() +
                                ", none) nor a number of mm/h in [0, " + std::to_string(int(kMaxRainMmPerHour)) + "]");
}

}  // namespace prism::water
