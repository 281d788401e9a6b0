// The usage example of prism/diffraction/stam_brdf.hpp, compiled and run by tests/snippets:
// 12.709 deg is the first order of a 2500 nm grating at 550 nm (sin = 550 / 2500).
// [snippet]
#include "prism/diffraction/stam_brdf.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), StamBrdf::Options{});
    double r = brdf.spectral(fromAngles(0, 0), fromAngles(12.709, 0), 550);  // first order
    Xyz c = brdf.xyz(fromAngles(0, 0), fromAngles(12.709, 0), spectralWeights(5));
    // [/snippet]
    const double between = brdf.spectral(fromAngles(0, 0), fromAngles(6.0, 0), 550);
    return r > 0.01 && c.y > 0.0 && between < 1e-3 * r ? 0 : 1;
}
