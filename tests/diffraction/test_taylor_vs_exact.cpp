// The Taylor path against the exact path (FFT of exp(i k w h), no series) over a strip of
// outgoing angles and 380-780 nm, and the mean subtraction that makes the series converge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "prism/diffraction/stam_brdf.hpp"
#include "prism/diffraction/taylor_bound.hpp"

using namespace prism::diffraction;

namespace {

// max |taylor - exact| / max exact over the strip.
double stripError(int terms) {
    const HeightField field = sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 150.0, .periods = 16});
    const StamBrdf taylor(field, {.path = StamBrdf::Path::Taylor, .terms = terms});
    const StamBrdf exact(field, {.path = StamBrdf::Path::Exact, .terms = terms});
    const Direction toLight = fromAngles(30.0, 180.0);
    double maxError = 0.0, maxValue = 0.0;
    for (double lambda = 380.0; lambda <= 780.0; lambda += 20.0) {
        for (double theta = -80.0; theta <= 80.0; theta += 0.25) {
            const Direction toViewer = fromAngles(theta, 0.0);
            const double e = exact.spectral(toLight, toViewer, lambda);
            maxError = std::max(maxError, std::abs(taylor.spectral(toLight, toViewer, lambda) - e));
            maxValue = std::max(maxValue, e);
        }
    }
    return maxError / maxValue;
}

}  // namespace

TEST(DiffractionTaylorVsExact, TwentyFiveTermsWithinOneInAMillion) {
    const double error = stripError(25);
    std::printf("Taylor N = 25 vs exact: relative Linf %.3g\n", error);
    EXPECT_LE(error, 1e-6);
}

TEST(DiffractionTaylorVsExact, TenTermsAreFarOff) {
    // The bound asks for ~25 terms at A = 150 nm; 10 is visibly wrong (the bound means something).
    const double error = stripError(10);
    std::printf("Taylor N = 10 vs exact: relative Linf %.3g\n", error);
    EXPECT_GT(error, 0.05);
}

TEST(DiffractionTaylorVsExact, MeanSubtractionLeavesPowerUnchanged) {
    HeightField field = snakeRidges({.size = 64});
    HeightField shifted = field;
    for (double& h : shifted.heightsNm) h += 1000.0;
    const double phase = 2.0 * std::numbers::pi / 500.0 * 1.7;
    const Spectrum a = exactSpectrum(field, phase), b = exactSpectrum(shifted, phase);
    const GaussianWindow window = defaultWindow(field);
    for (double f : {0.0, 1.0 / 1400.0, 2.3 / 1400.0}) {
        EXPECT_NEAR(std::norm(a.evaluate(f, 0.2 * f, window)), std::norm(b.evaluate(f, 0.2 * f, window)), 1e-12);
    }
}

TEST(DiffractionTaylorVsExact, MeanSubtractionIsWhatMakesTheSeriesConverge) {
    // Without it, a blazed grating's heights reach 2A instead of A and the series of the same
    // length is much further from the exact spectrum.
    const HeightField raw = blazedGrating({.periodNm = 2500.0, .amplitudeNm = 150.0, .periods = 8});
    HeightField centred = raw;
    subtractMean(centred);
    const double k = 2.0 * std::numbers::pi / 380.0, w = 2.0;
    const GaussianWindow window = defaultWindow(raw);
    const double f = 1.0 / 2500.0;
    const double exactPower = std::norm(exactSpectrum(raw, k * w).evaluate(f, 0.0, window));
    const double centredError =
        std::abs(std::norm(taylorSpectra(centred, 20).evaluate(f, 0.0, k, w, window)) - exactPower);
    const double rawError = std::abs(std::norm(taylorSpectra(raw, 20).evaluate(f, 0.0, k, w, window)) - exactPower);
    EXPECT_LT(centredError, 1e-3 * exactPower);
    EXPECT_GT(rawError, 100.0 * centredError);
}

TEST(DiffractionTaylorVsExact, ConstantOffsetChangesNothing) {
    // StamBrdf subtracts the mean: a 5 um offset neither raises N (it would need > 200 terms)
    // nor changes the BRDF.
    const HeightField plain = sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 150.0, .periods = 8});
    HeightField lifted = plain;
    for (double& h : lifted.heightsNm) h += 5000.0;
    const StamBrdf a(plain, StamBrdf::Options{}), b(lifted, StamBrdf::Options{});
    EXPECT_EQ(a.terms(), b.terms());
    EXPECT_EQ(a.terms(), termsForTolerance(150.0, kLambdaMinNm, 1e-6));
    for (double theta : {0.0, 12.709, 20.0}) {
        const double va = a.spectral(fromAngles(0, 0), fromAngles(theta, 0), 550.0);
        EXPECT_NEAR(b.spectral(fromAngles(0, 0), fromAngles(theta, 0), 550.0), va, 1e-9 * (1.0 + va)) << theta;
    }
}
