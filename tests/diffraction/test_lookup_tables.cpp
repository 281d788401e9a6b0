// The GPU paths' lookup tables, emulated in double precision on the CPU: they converge to the
// table-free reference as the table grows, path (b) agrees with path (a), and a surface only
// gets the layers its terms need.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "prism/diffraction/lookup_tables.hpp"

using namespace prism::diffraction;

namespace {

// A grating with short coherence (sigma 1 um), so its orders are a few table cells wide.
const StamBrdf& grating() {
    static const StamBrdf brdf(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 60.0, .periods = 8}),
                               {.tolerance = 1e-5, .window = GaussianWindow{1000.0, 4.0}});
    return brdf;
}

double channelMax(LinearRgb c) {
    return std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)});
}
LinearRgb minus(LinearRgb a, LinearRgb b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}

template <typename Shade>
double stripError(Shade shade, int stepNm) {
    const std::vector<SpectralWeight> weights = spectralWeights(stepNm);
    double maxError = 0.0, maxValue = 0.0;
    for (double theta = -80.0; theta <= 80.0; theta += 0.5) {
        const Direction wi = fromAngles(30.0, 180.0), wr = fromAngles(theta, 0.0);
        const LinearRgb reference = shadeReference(grating(), wi, wr, weights);
        maxError = std::max(maxError, channelMax(minus(shade(wi, wr), reference)));
        maxValue = std::max(maxValue, channelMax(reference));
    }
    return maxError / maxValue;
}

}  // namespace

TEST(DiffractionLookupTables, SpectralPathConvergesWithTableSize) {
    double previous = 1e9;
    for (int size : {64, 256, 1024}) {
        const SpectralTables a = buildSpectralTables(grating(), {.size = size, .wavelengthStepNm = 10});
        const double error = stripError([&](Direction wi, Direction wr) { return shadeSpectral(a, wi, wr); }, 10);
        std::printf("path a, %d^2: relative Linf %.3g\n", size, error);
        EXPECT_LT(error, previous);
        previous = error;
    }
    EXPECT_LT(previous, 0.005);  // bilinear: error falls ~4x per doubling
}

TEST(DiffractionLookupTables, IntegratedPathConvergesWithTableSize) {
    double previous = 1e9;
    for (int size : {64, 256}) {
        const SpectralTables a = buildSpectralTables(grating(), {.size = size, .wavelengthStepNm = 20});
        const IntegratedTables b = buildIntegratedTables(a);
        const double error = stripError([&](Direction wi, Direction wr) { return shadeIntegrated(b, wi, wr); }, 20);
        std::printf("path b, %d^2: relative Linf %.3g\n", size, error);
        EXPECT_LT(error, previous);
        previous = error;
    }
    EXPECT_LT(previous, 0.05);
}

TEST(DiffractionLookupTables, OnlyTheNeededLayersAreBuilt) {
    const StamBrdf mirror(sinusoidGrating({.amplitudeNm = 0.0, .periods = 4}), StamBrdf::Options{});
    const SpectralTables a = buildSpectralTables(mirror, {.size = 16, .wavelengthStepNm = 20});
    EXPECT_EQ(a.terms, 0);
    EXPECT_EQ(a.bytes(), 16u * 16u * 2u * sizeof(float));
    EXPECT_EQ(buildIntegratedTables(a).bytes(), 16u * 16u * 3u * sizeof(float));
    const SpectralTables g = buildSpectralTables(grating(), {.size = 16, .wavelengthStepNm = 20});
    EXPECT_EQ(g.terms, grating().terms());
    EXPECT_EQ(g.bytes(), (grating().terms() + 1u) * 16u * 16u * 2u * sizeof(float));
    // A mirror's tables give white at the specular direction (rho = 1 there).
    const LinearRgb white = shadeSpectral(a, fromAngles(0, 0), fromAngles(0, 0));
    EXPECT_NEAR(white.r, 1.0, 1e-3);
    EXPECT_NEAR(white.g, 1.0, 1e-3);
    EXPECT_NEAR(white.b, 1.0, 1e-3);
}

TEST(DiffractionLookupTables, ExtremesStayFinite) {
    const SpectralTables a = buildSpectralTables(grating(), {.size = 32, .wavelengthStepNm = 20});
    const IntegratedTables b = buildIntegratedTables(a);
    const Direction cases[][2] = {{fromAngles(89.9, 180), fromAngles(89.9, 0)},
                                  {fromAngles(100, 180), fromAngles(10, 0)},
                                  {fromAngles(90, 180), fromAngles(90, 0)}};
    for (const auto& c : cases) {
        for (const LinearRgb v : {shadeSpectral(a, c[0], c[1]), shadeIntegrated(b, c[0], c[1])}) {
            EXPECT_TRUE(std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b));
        }
    }
    EXPECT_THROW(buildSpectralTables(StamBrdf(sinusoidGrating({}), {.path = StamBrdf::Path::Exact}), {}),
                 std::invalid_argument);
}

TEST(DiffractionLookupTables, VolumePathConvergesToIntegratedWithSlices) {
    const SpectralTables a = buildSpectralTables(grating(), {.size = 64, .wavelengthStepNm = 20});
    const IntegratedTables b = buildIntegratedTables(a);
    double previous = 1e9;
    for (int slices : {4, 16, 64}) {
        const VolumeTables c = buildVolumeTables(b, slices);
        double maxError = 0.0, maxValue = 0.0;
        for (double theta = -80.0; theta <= 80.0; theta += 0.5) {
            const Direction wi = fromAngles(30.0, 180.0), wr = fromAngles(theta, 0.0);
            const LinearRgb want = shadeIntegrated(b, wi, wr);
            maxError = std::max(maxError, channelMax(minus(shadeVolume(c, wi, wr), want)));
            maxValue = std::max(maxValue, channelMax(want));
        }
        std::printf("path c, %d slices vs path b: relative Linf %.3g\n", slices, maxError / maxValue);
        EXPECT_LT(maxError / maxValue, previous);
        previous = maxError / maxValue;
    }
    EXPECT_LT(previous, 0.01);
    EXPECT_THROW(buildVolumeTables(b, 1), std::invalid_argument);
}
