// The usage example of prism/diffraction/peaks.hpp, compiled and run by tests/snippets.
#include <cmath>
// [snippet]
#include "prism/diffraction/peaks.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), {});
    std::vector<Peak> peaks = findPeaks(brdf, {.incidenceDeg = 0, .wavelengthsNm = {550}, .periodNm = 2500});
    // one peak per order, e.g. {550, -1, -12.709, 0.05...} and {550, 1, 12.709, ...}
    // [/snippet]
    bool first = false, minusFirst = false;
    for (const Peak& p : peaks) {
        if (p.order == 1) first = std::abs(p.angleDeg - 12.709) < 0.01;
        if (p.order == -1) minusFirst = std::abs(p.angleDeg + 12.709) < 0.01;
    }
    return peaks.size() >= 3 && first && minusFirst ? 0 : 1;
}
