// The usage example of prism/diffraction/height_field.hpp, compiled and run by tests/snippets.
#include <cmath>
// [snippet]
#include "prism/diffraction/height_field.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    HeightField grating = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
    subtractMean(grating);                // lowers k w h_max; |P|^2 is unchanged
    double hMax = maxAbsHeight(grating);  // 150 nm, feeds termsForTolerance()
    // [/snippet]
    return std::abs(hMax - 150.0) < 1e-9 ? 0 : 1;
}
