// Numerical extremes of the reference BRDF: grazing angles, light below the horizon, w -> 0,
// A = 0 (a mirror), A too large for the series, 1 and 20 nm wavelength steps.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/diffraction/stam_brdf.hpp"
#include "prism/diffraction/taylor_bound.hpp"

using namespace prism::diffraction;

namespace {

const StamBrdf& grating() {
    static const StamBrdf brdf(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 150.0, .periods = 16}),
                               StamBrdf::Options{});
    return brdf;
}

bool finite(const Xyz& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

}  // namespace

TEST(DiffractionExtremes, GrazingLightAndViewAreFinite) {
    const std::vector<SpectralWeight> weights = spectralWeights(5);
    for (double phi : {0.0, 90.0, 180.0}) {
        const Xyz c = grating().xyz(fromAngles(89.9, 180.0), fromAngles(89.9, phi), weights);
        EXPECT_TRUE(finite(c)) << phi;
        EXPECT_GE(c.y, 0.0);
    }
    // The specular direction at grazing incidence is a proper order-0 peak, not 0 and not inf.
    const double specular = grating().spectral(fromAngles(89.9, 180.0), fromAngles(89.9, 0.0), 550.0);
    EXPECT_TRUE(std::isfinite(specular));
    EXPECT_GT(specular, 0.0);
}

TEST(DiffractionExtremes, LightBelowTheHorizonGivesZero) {
    const Direction below = fromAngles(100.0, 180.0);
    EXPECT_EQ(grating().spectral(below, fromAngles(10.0, 0.0), 550.0), 0.0);
    const Xyz c = grating().xyz(below, fromAngles(80.0, 0.0), spectralWeights(5));
    EXPECT_EQ(c.x, 0.0);
    EXPECT_EQ(c.y, 0.0);
    EXPECT_EQ(c.z, 0.0);
    EXPECT_EQ(grating().spectral(fromAngles(10.0, 0.0), fromAngles(90.0, 0.0), 550.0), 0.0);  // view on the horizon
}

TEST(DiffractionExtremes, OppositeDirectionsWhereWVanishes) {
    // wi = -wr gives (u, v, w) = 0; both on the horizon, or one below it.
    for (double theta : {90.0, 89.99999, 45.0, 0.0}) {
        const Direction wi = fromAngles(theta, 180.0);
        const Direction wr{-wi.x, -wi.y, -wi.z};
        const StamGeometry g = stamGeometry(wi, wr);
        EXPECT_TRUE(std::isfinite(g.factor)) << theta;
        EXPECT_TRUE(std::isfinite(grating().spectral(wi, wr, 550.0))) << theta;
    }
    // Just above the horizon on both sides, w is tiny but the factor stays finite.
    const StamGeometry nearly = stamGeometry(fromAngles(89.9999, 180.0), fromAngles(89.9999, 0.0));
    EXPECT_TRUE(std::isfinite(nearly.factor));
    EXPECT_GT(nearly.factor, 0.0);
}

TEST(DiffractionExtremes, ZeroAmplitudeIsAMirror) {
    const StamBrdf mirror(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 0.0, .periods = 16}),
                          StamBrdf::Options{});
    EXPECT_EQ(mirror.terms(), 0);
    // Normal incidence: exactly 1 at the specular direction (the normalisation of the relative BRDF).
    EXPECT_NEAR(mirror.spectral(fromAngles(0, 0), fromAngles(0, 0), 550.0), 1.0, 1e-12);
    // No diffraction orders: nothing at the first-order angle.
    EXPECT_LT(mirror.spectral(fromAngles(0, 0), fromAngles(12.709, 0), 550.0), 1e-12);
    // In the specular direction G / w^2 = (2 cos^2)^2 / (cos^2 4 cos^2) = 1 at every angle.
    for (double theta : {40.0, 85.0, 89.9}) {
        EXPECT_NEAR(mirror.spectral(fromAngles(theta, 180), fromAngles(theta, 0), 550.0), 1.0, 1e-9) << theta;
    }
}

TEST(DiffractionExtremes, HugeAmplitudeIsAClearError) {
    try {
        StamBrdf huge(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 20000.0, .periods = 4}), StamBrdf::Options{});
        FAIL() << "no error for A = 20 um";
    } catch (const TooManyTermsError& e) {
        EXPECT_NE(std::string(e.what()).find("Taylor terms"), std::string::npos) << e.what();
    }
    // The exact path needs no series: the same surface stays finite there.
    const StamBrdf exact(sinusoidGrating({.amplitudeNm = 20000.0, .periods = 4}), {.path = StamBrdf::Path::Exact});
    const Xyz c = exact.xyz(fromAngles(10, 180), fromAngles(10, 0), spectralWeights(20));
    EXPECT_TRUE(finite(c));
}

TEST(DiffractionExtremes, CoarseAndFineWavelengthStepsAreFinite) {
    for (int step : {1, 20}) {
        const Xyz c = grating().xyz(fromAngles(20, 180), fromAngles(5, 0), spectralWeights(step));
        EXPECT_TRUE(finite(c)) << step;
        EXPECT_GT(c.y, 0.0) << step;
    }
}

TEST(DiffractionExtremes, NonFiniteDirectionsAreErrors) {
    EXPECT_THROW(stamGeometry({NAN, 0, 1}, {0, 0, 1}), std::invalid_argument);
    EXPECT_THROW(stamGeometry({0, 0, 2}, {0, 0, 1}), std::invalid_argument);
    EXPECT_THROW(grating().spectral({0, 0, 1}, {0, 0, 1}, 0.0), std::invalid_argument);
}
