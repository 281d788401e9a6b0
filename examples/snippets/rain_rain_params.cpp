// The usage example of prism/rain/rain_params.hpp, compiled and run by tests/snippets.
#include <iostream>

// [snippet]
#include "prism/rain/rain_params.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::rain::RainParams p;  // moderate rain
    p.intensity = prism::rain::rainClassInfo(prism::rain::RainClass::Heavy).intensity;
    p.wind.strength = 4.0f;                              // m/s, random direction
    prism::rain::validate(p);                            // throws RainParameterError
    std::uint32_t n = prism::rain::particleCountFor(p);  // 41,933 (heavy, defaults)
    // [/snippet]
    std::cout << n << " particles\n";
    return n == 41933 ? 0 : 1;  // the number the comment states
}
