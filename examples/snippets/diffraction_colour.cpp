// The usage example of prism/diffraction/colour.hpp, compiled and run by tests/snippets.
#include <cmath>
// [snippet]
#include "prism/diffraction/colour.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    std::vector<SpectralWeight> grid = spectralWeights(5);       // 81 wavelengths
    Xyz white{};                                                 // a flat reflectance of 1
    for (const SpectralWeight& s : grid) white = white + s.xyz;  // = D65 white, Y = 1
    LinearRgb rgb = xyzToLinearSrgb(white);                      // ~ (1, 1, 1)
    // [/snippet]
    const bool ok = grid.size() == 81 && std::abs(white.y - 1.0) < 1e-9 && std::abs(rgb.r - 1.0) < 1e-3 &&
                    std::abs(rgb.g - 1.0) < 1e-3 && std::abs(rgb.b - 1.0) < 1e-3;
    return ok ? 0 : 1;
}
