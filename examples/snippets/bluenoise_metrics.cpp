// The usage example of prism/bluenoise/metrics.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/bluenoise/metrics.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::bluenoise::GrayImage image{2, 1, 8, {0, 255}};         // width, height, bits, values
    bool uniform = prism::bluenoise::histogramUniform(image);     // levels as even as N allows
    double lf = prism::bluenoise::lowFrequencyPowerRatio(image);  // white noise ~ 1, blue << 1
    double fast = prism::bluenoise::filteredErrorSigma1(image);   // white noise ~ 0.114
    double aniso = prism::bluenoise::anisotropyDb(image);         // white noise ~ 0 dB
    std::vector<prism::bluenoise::SpectrumRing> rings = prism::bluenoise::radialPowerSpectrum(image);
    // [/snippet]
    // 2 pixels: each level at most once (uniform); the only non-DC frequency is 1/2, so no
    // frequency below 1/8 (ratio 0).
    if (!uniform || lf != 0.0 || !std::isfinite(fast) || fast <= 0.0 || !std::isfinite(aniso) || rings.empty())
        return 1;
    // A white-noise image of 64x64 is close to the values in the comments.
    const prism::bluenoise::GrayImage white = prism::bluenoise::whiteNoiseImage(64, 64, 8, 3);
    return std::abs(prism::bluenoise::lowFrequencyPowerRatio(white) - 1.0) < 0.5 &&
                   std::abs(prism::bluenoise::filteredErrorSigma1(white) - 0.114) < 0.02
               ? 0
               : 1;
}
