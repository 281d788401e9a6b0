// Peak angles of the reference BRDF against the grating equation sin(theta_m) = sin(theta_i) + m
// lambda / d for a d = 2500 nm, A = 150 nm sinusoidal grating (expected angles from
// docs/references.md, "Grating equation", computed independently of this code), and the +-m symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "prism/diffraction/peaks.hpp"

using namespace prism::diffraction;

namespace {

constexpr double kPeriodNm = 2500.0;
constexpr double kToleranceDeg = 0.05;

const StamBrdf& grating() {
    static const StamBrdf brdf(sinusoidGrating({.periodNm = kPeriodNm, .amplitudeNm = 150.0}), StamBrdf::Options{});
    return brdf;
}

std::map<int, Peak> peaksByOrder(double incidenceDeg, double lambda) {
    std::map<int, Peak> byOrder;
    for (const Peak& p :
         findPeaks(grating(), {.incidenceDeg = incidenceDeg, .wavelengthsNm = {lambda}, .periodNm = kPeriodNm})) {
        EXPECT_EQ(byOrder.count(p.order), 0u) << "two peaks of order " << p.order << " at " << lambda << " nm";
        byOrder[p.order] = p;
    }
    return byOrder;
}

}  // namespace

TEST(DiffractionGratingEquation, NormalIncidenceFirstAndSecondOrders) {
    const struct {
        double lambda, first, second;
    } expected[] = {{400, 9.207, 18.663}, {550, 12.709, 26.104}, {700, 16.260, 34.056}};
    for (const auto& e : expected) {
        std::map<int, Peak> peaks = peaksByOrder(0.0, e.lambda);
        ASSERT_TRUE(peaks.count(1) && peaks.count(-1) && peaks.count(2) && peaks.count(-2)) << e.lambda;
        EXPECT_NEAR(peaks[1].angleDeg, e.first, kToleranceDeg) << e.lambda;
        EXPECT_NEAR(peaks[-1].angleDeg, -e.first, kToleranceDeg) << e.lambda;
        EXPECT_NEAR(peaks[2].angleDeg, e.second, kToleranceDeg) << e.lambda;
        EXPECT_NEAR(peaks[-2].angleDeg, -e.second, kToleranceDeg) << e.lambda;
        EXPECT_NEAR(peaks[0].angleDeg, 0.0, kToleranceDeg) << e.lambda;
    }
}

TEST(DiffractionGratingEquation, SeventyFiveDegreesOrderMinusOne) {
    const struct { double lambda, angle; } expected[] = {{400, 53.700}, {550, 48.239}, {700, 43.308}};
    for (const auto& e : expected) {
        std::map<int, Peak> peaks = peaksByOrder(75.0, e.lambda);
        ASSERT_TRUE(peaks.count(-1) && peaks.count(0)) << e.lambda;
        EXPECT_NEAR(peaks[-1].angleDeg, e.angle, kToleranceDeg) << e.lambda;
        EXPECT_NEAR(peaks[0].angleDeg, 75.0, kToleranceDeg) << e.lambda;
    }
}

TEST(DiffractionGratingEquation, NormalIncidencePlusAndMinusOrdersAgree) {
    for (double lambda : {400.0, 550.0, 700.0}) {
        std::map<int, Peak> peaks = peaksByOrder(0.0, lambda);
        for (int m : {1, 2, 3}) {
            ASSERT_TRUE(peaks.count(m) && peaks.count(-m)) << lambda << " nm order " << m;
            EXPECT_GT(peaks[m].relativeIntensity, 1e-4);
            EXPECT_NEAR(peaks[m].relativeIntensity / peaks[-m].relativeIntensity, 1.0, 0.01)
                << lambda << " nm order " << m;
        }
    }
}

TEST(DiffractionGratingEquation, BlazedGratingFavoursOneSide) {
    // A sawtooth is not mirror-symmetric, so +1 and -1 differ; the sinusoid test above would
    // not notice an evaluation that symmetrises the spectrum, this one would.
    StamBrdf blazed(blazedGrating({.periodNm = kPeriodNm, .amplitudeNm = 100.0}), StamBrdf::Options{});
    std::map<int, Peak> byOrder;
    for (const Peak& p : findPeaks(blazed, {.incidenceDeg = 0.0, .wavelengthsNm = {550}, .periodNm = kPeriodNm}))
        byOrder[p.order] = p;
    ASSERT_TRUE(byOrder.count(1) && byOrder.count(-1));
    EXPECT_NEAR(byOrder[1].angleDeg, 12.709, kToleranceDeg);
    const double ratio = byOrder[1].relativeIntensity / byOrder[-1].relativeIntensity;
    EXPECT_TRUE(ratio > 1.5 || ratio < 1.0 / 1.5) << ratio;
}

TEST(DiffractionGratingEquation, FirstOrderIntensityFollowsBessel) {
    // For a sinusoid, |c_m| = |J_m(k w A)| (Jacobi-Anger), so at normal incidence the order-1 /
    // order-0 ratio is G/w^2 (first order) * J_1(kwA)^2 / J_0(2kA)^2, with w from the geometry.
    const double lambda = 550.0, k = 2.0 * std::numbers::pi / lambda;
    std::map<int, Peak> peaks = peaksByOrder(0.0, lambda);
    const double t = peaks[1].angleDeg * std::numbers::pi / 180.0;
    const double w1 = 1.0 + std::cos(t);
    const double factor1 = std::pow((1.0 + std::cos(t)) / w1, 2) / std::cos(t);
    const double expected = factor1 * std::pow(std::cyl_bessel_j(1.0, k * w1 * 150.0), 2) /
                            std::pow(std::cyl_bessel_j(0.0, k * 2.0 * 150.0), 2);
    EXPECT_NEAR(peaks[1].relativeIntensity / expected, 1.0, 0.01);
}
