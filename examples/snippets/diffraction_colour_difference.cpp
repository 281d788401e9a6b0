// The usage example of prism/diffraction/colour_difference.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/diffraction/colour_difference.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    Lab a = linearSrgbToLab({0.5, 0.2, 0.1}), b = linearSrgbToLab({0.5, 0.21, 0.1});
    double dE = ciede2000(a, b);  // ~1 is a just-noticeable difference
    // [/snippet]
    return dE > 0.3 && dE < 3.0 && ciede2000(a, a) == 0.0 ? 0 : 1;
}
