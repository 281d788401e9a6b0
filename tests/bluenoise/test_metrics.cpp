// Mask metrics against references: Parseval for the spectrum, white noise (LF ratio ~1,
// FAST ~0.114, anisotropy ~0 dB), pure patterns with known spectra, and extremes
// (1x1, constant black and white images: finite, no division by zero).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/bluenoise/metrics.hpp"

namespace bn = prism::bluenoise;

namespace {

bn::GrayImage pattern(int w, int h, auto f) {
    bn::GrayImage image{w, h, 8, std::vector<std::uint16_t>(static_cast<std::size_t>(w * h))};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.values[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint16_t>(f(x, y));
    return image;
}

bool finite(const bn::MaskMetrics& m) {
    return std::isfinite(m.lowFrequencyPowerRatio) && std::isfinite(m.filteredErrorSigma1) &&
           std::isfinite(m.anisotropyDb);
}

}  // namespace

TEST(Metrics, WhiteNoiseReferenceValues) {
    const bn::GrayImage white = bn::whiteNoiseImage(128, 128, 8, 3);
    EXPECT_NEAR(bn::lowFrequencyPowerRatio(white), 1.0, 0.15);
    EXPECT_NEAR(bn::filteredErrorSigma1(white), 0.114, 0.006);
    EXPECT_NEAR(bn::anisotropyDb(white), 0.0, 1.0);
    // Radially averaged spectrum of white noise is flat at 1.
    double sum = 0.0;
    int n = 0;
    for (const auto& r : bn::radialPowerSpectrum(white))
        if (r.frequency > 0.05 && r.frequency < 0.5) sum += r.power, ++n;
    EXPECT_NEAR(sum / n, 1.0, 0.05);
}

TEST(Metrics, RadialSpectrumPeaksAtACosinesFrequency) {
    // cos with period 8 px along x and 16 px along y: |f| = sqrt(1/64 + 1/256) = 0.1398.
    const auto wave =
        pattern(64, 64, [](int x, int y) { return 128 + 120 * std::cos(2 * std::numbers::pi * (x / 8.0 + y / 16.0)); });
    const auto rings = bn::radialPowerSpectrum(wave);
    std::size_t peak = 0;
    for (std::size_t i = 0; i < rings.size(); ++i)
        if (rings[i].power > rings[peak].power) peak = i;
    EXPECT_NEAR(rings[peak].frequency, 0.1398, 0.5 / 64);
    double elsewhere = 0.0;
    for (std::size_t i = 0; i < rings.size(); ++i)
        if (i != peak) elsewhere += rings[i].power * rings[i].count;
    // Quantisation to 8 bits leaves a little power elsewhere; almost all is in the peak.
    EXPECT_LT(elsewhere, 0.01 * rings[peak].power * rings[peak].count);
}

TEST(Metrics, LowFrequencyPatternHasHighRatioHighFrequencyPatternZero) {
    // cos with period 16 px: f = 1/16 < 1/8, all its power is low-frequency.
    const auto low = pattern(64, 64, [](int x, int) { return 128 + 100 * std::cos(2 * std::numbers::pi * x / 16.0); });
    // All power sits in 2 of the ~200 low-frequency bins out of 4095: ratio ~ 4095 / 200.
    EXPECT_GT(bn::lowFrequencyPowerRatio(low), 15.0);
    // Checkerboard: all power at (1/2, 1/2).
    const auto high = pattern(64, 64, [](int x, int y) { return ((x + y) & 1) ? 255 : 0; });
    EXPECT_LT(bn::lowFrequencyPowerRatio(high), 1e-9);
}

TEST(Metrics, StripesAreAnisotropic) {
    bn::GrayImage white = bn::whiteNoiseImage(64, 64, 8, 5);
    // Each column a constant: all power on the kx axis.
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            white.values[static_cast<std::size_t>(y * 64 + x)] = white.values[static_cast<std::size_t>(x)];
    EXPECT_GT(bn::anisotropyDb(white), 5.0);
}

TEST(Metrics, HistogramUniformity) {
    auto ramp = pattern(16, 16, [](int x, int y) { return y * 16 + x; });
    EXPECT_TRUE(bn::histogramUniform(ramp));
    ramp.values[0] = 1;  // level 0 missing, level 1 twice
    EXPECT_FALSE(bn::histogramUniform(ramp));
    // 16-bit images are judged by their top 8 bits.
    bn::GrayImage wide{16, 16, 16, {}};
    for (int i = 0; i < 256; ++i) wide.values.push_back(static_cast<std::uint16_t>(i * 256 + 255));
    EXPECT_TRUE(bn::histogramUniform(wide));
}

TEST(Metrics, ExtremesAreFinite) {
    const auto black = pattern(32, 32, [](int, int) { return 0; });
    const auto whiteImage = pattern(32, 32, [](int, int) { return 255; });
    const auto one = pattern(1, 1, [](int, int) { return 17; });
    const auto line = pattern(1, 50, [](int, int y) { return (y * 5) % 256; });
    for (const auto* image : {&black, &whiteImage, &one, &line}) {
        const bn::MaskMetrics m = bn::measureMask(*image);
        EXPECT_TRUE(finite(m));
        for (const auto& r : bn::radialPowerSpectrum(*image)) EXPECT_TRUE(std::isfinite(r.power));
    }
    EXPECT_FALSE(bn::histogramUniform(black));
    EXPECT_EQ(bn::lowFrequencyPowerRatio(black), 0.0);
    EXPECT_EQ(bn::anisotropyDb(black), 0.0);
    // Constant images are the worst dither: far above white noise.
    EXPECT_GT(bn::filteredErrorSigma1(black), 0.5);
    EXPECT_GT(bn::filteredErrorSigma1(whiteImage), 0.5);
}

TEST(Metrics, BadImagesThrow) {
    bn::GrayImage wrongCount{4, 4, 8, std::vector<std::uint16_t>(15)};
    EXPECT_THROW(bn::lowFrequencyPowerRatio(wrongCount), std::invalid_argument);
    bn::GrayImage wrongBits{1, 1, 12, {0}};
    EXPECT_THROW(bn::filteredErrorSigma1(wrongBits), std::invalid_argument);
    EXPECT_THROW(bn::gaussianBlur(bn::RealImage{1, 1, {0.0}}, 0.0), std::invalid_argument);
}
