// The usage example of prism/rain/rain_classes.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/rain/rain_classes.hpp"
// [/snippet]

int main() {
    // [snippet]
    const prism::rain::RainClassInfo& heavy = prism::rain::rainClassInfo(prism::rain::RainClass::Heavy);
    float cmPerHour = heavy.intensity;                                                    // 1.524
    double mmPerHour = prism::rain::rainRateMmPerHour(prism::rain::RainClass::Moderate);  // 3.81
    auto c = prism::rain::parseRainClass("Cloudburst");                                   // RainClass::Cloudburst
    // [/snippet]
    return std::abs(cmPerHour - 1.524f) < 1e-6f && std::abs(mmPerHour - 3.81) < 1e-6 &&
                   c == prism::rain::RainClass::Cloudburst
               ? 0
               : 1;
}
