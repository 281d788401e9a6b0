// The usage example of prism/diffraction/spectrum.hpp, compiled and run by tests/snippets:
// the Taylor and the exact spectrum agree at the first order of a grating.
#include <cmath>
// [snippet]
#include "prism/diffraction/spectrum.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    HeightField g = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
    subtractMean(g);
    TaylorSpectra taylor = taylorSpectra(g, /*terms N*/ 25);  // FFTs of h^0..h^N
    GaussianWindow window = defaultWindow(g);
    std::complex<double> p = taylor.evaluate(1.0 / 2500, 0.0, /*k*/ 2 * 3.14159265 / 550, /*w*/ 2.0, window);
    Spectrum exact = exactSpectrum(g, 2 * 3.14159265 / 550 * 2.0);     // no Taylor series
    std::complex<double> q = exact.evaluate(1.0 / 2500, 0.0, window);  // ~ p
    // [/snippet]
    return std::abs(p - q) < 1e-6 && std::abs(p) > 0.01 ? 0 : 1;
}
