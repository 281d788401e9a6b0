// The usage example of prism/water/rain_rates.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/water/rain_rates.hpp"
// [/snippet]

int main() {
    // [snippet]
    double mmh = prism::water::rainRateMmPerHour(prism::water::RainClass::Heavy);  // 15.2
    double ms = prism::water::mmPerHourToMetresPerSecond(mmh);                     // 4.22e-6
    double r = prism::water::parseRainRateMmPerHour("cloudburst");                 // 101.6
    double c = prism::water::parseRainRateMmPerHour("12.5");                       // 12.5 (mm/h)
    // [/snippet]
    const auto near = [](double a, double b) { return std::abs(a - b) <= 0.01 * std::abs(b); };
    return near(mmh, 15.2) && near(ms, 4.22e-6) && near(r, 101.6) && c == 12.5 ? 0 : 1;
}
