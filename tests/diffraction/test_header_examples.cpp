// The usage examples at the top of prism_diffraction_core's public headers, compiled and run
// (each block is copied from its header's comment).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/diffraction/colour.hpp"
#include "prism/diffraction/colour_difference.hpp"
#include "prism/diffraction/height_field.hpp"
#include "prism/diffraction/lookup_tables.hpp"
#include "prism/diffraction/peaks.hpp"
#include "prism/diffraction/spectrum.hpp"
#include "prism/diffraction/stam_brdf.hpp"
#include "prism/diffraction/taylor_bound.hpp"

TEST(DiffractionHeaderExamples, Colour) {
    using namespace prism::diffraction;
    std::vector<SpectralWeight> grid = spectralWeights(5);       // 81 wavelengths
    Xyz white{};                                                 // a flat reflectance of 1
    for (const SpectralWeight& s : grid) white = white + s.xyz;  // = D65 white, Y = 1
    LinearRgb rgb = xyzToLinearSrgb(white);                      // ~ (1, 1, 1)
    EXPECT_EQ(grid.size(), 81u);
    EXPECT_NEAR(rgb.g, 1.0, 1e-3);
}

TEST(DiffractionHeaderExamples, HeightField) {
    using namespace prism::diffraction;
    HeightField grating = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
    subtractMean(grating);                // lowers k w h_max; |P|^2 is unchanged
    double hMax = maxAbsHeight(grating);  // 150 nm, feeds termsForTolerance()
    EXPECT_NEAR(hMax, 150.0, 1e-9);
}

TEST(DiffractionHeaderExamples, Spectrum) {
    using namespace prism::diffraction;
    HeightField g = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
    subtractMean(g);
    TaylorSpectra taylor = taylorSpectra(g, /*terms N*/ 25);  // FFTs of h^0..h^N
    GaussianWindow window = defaultWindow(g);
    std::complex<double> p = taylor.evaluate(1.0 / 2500, 0.0, /*k*/ 2 * 3.14159265 / 550, /*w*/ 2.0, window);
    Spectrum exact = exactSpectrum(g, 2 * 3.14159265 / 550 * 2.0);     // no Taylor series
    std::complex<double> q = exact.evaluate(1.0 / 2500, 0.0, window);  // ~ p
    EXPECT_NEAR(std::abs(p - q), 0.0, 1e-6);
}

TEST(DiffractionHeaderExamples, TaylorBound) {
    using namespace prism::diffraction;
    double x = taylorArgument(/*h_max nm*/ 150, /*lambda_min nm*/ 380);  // 4.96
    int n = termsForTolerance(150, 380, 1e-6);                           // smallest N with bound <= 1e-6
    double e = taylorErrorBound(x, n);                                   // <= 1e-6
    EXPECT_NEAR(x, 4.96, 0.005);
    EXPECT_LE(e, 1e-6);
}

TEST(DiffractionHeaderExamples, StamBrdf) {
    using namespace prism::diffraction;
    StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), StamBrdf::Options{});
    double r = brdf.spectral(fromAngles(0, 0), fromAngles(12.709, 0), 550);  // first order
    Xyz c = brdf.xyz(fromAngles(0, 0), fromAngles(12.709, 0), spectralWeights(5));
    EXPECT_GT(r, 0.01);
    EXPECT_GT(c.y, 0.0);
}

TEST(DiffractionHeaderExamples, Peaks) {
    using namespace prism::diffraction;
    StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), {});
    std::vector<Peak> peaks = findPeaks(brdf, {.incidenceDeg = 0, .wavelengthsNm = {550}, .periodNm = 2500});
    EXPECT_GE(peaks.size(), 3u);
}

TEST(DiffractionHeaderExamples, LookupTables) {
    using namespace prism::diffraction;
    StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
    SpectralTables a = buildSpectralTables(brdf, {.size = 64, .wavelengthStepNm = 10});
    IntegratedTables b = buildIntegratedTables(a);
    LinearRgb viaA = shadeSpectral(a, fromAngles(30, 180), fromAngles(30, 0));
    LinearRgb viaB = shadeIntegrated(b, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaA
    VolumeTables c = buildVolumeTables(b, /*slices of w*/ 16);
    LinearRgb viaC = shadeVolume(c, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaB
    EXPECT_NEAR(viaA.g, viaB.g, 0.05 * viaA.g);
    EXPECT_NEAR(viaB.g, viaC.g, 0.01 * viaB.g);
}

TEST(DiffractionHeaderExamples, ColourDifference) {
    using namespace prism::diffraction;
    Lab a = linearSrgbToLab({0.5, 0.2, 0.1}), b = linearSrgbToLab({0.5, 0.21, 0.1});
    double dE = ciede2000(a, b);  // ~1 is a just-noticeable difference
    EXPECT_GT(dE, 0.3);
    EXPECT_LT(dE, 3.0);
}
