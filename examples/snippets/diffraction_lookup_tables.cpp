// The usage example of prism/diffraction/lookup_tables.hpp, compiled and run by tests/snippets:
// the three shader paths' CPU emulations agree.
#include <cmath>
// [snippet]
#include "prism/diffraction/lookup_tables.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
    SpectralTables a = buildSpectralTables(brdf, {.size = 64, .wavelengthStepNm = 10});
    IntegratedTables b = buildIntegratedTables(a);
    LinearRgb viaA = shadeSpectral(a, fromAngles(30, 180), fromAngles(30, 0));
    LinearRgb viaB = shadeIntegrated(b, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaA
    VolumeTables c = buildVolumeTables(b, /*slices of w*/ 16);
    LinearRgb viaC = shadeVolume(c, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaB
    // [/snippet]
    const bool ok =
        viaA.g > 0.0 && std::abs(viaA.g - viaB.g) <= 0.05 * viaA.g && std::abs(viaB.g - viaC.g) <= 0.01 * viaB.g;
    return ok ? 0 : 1;
}
