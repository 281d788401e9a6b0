// Quality metrics of a dither mask (or of any grey image, e.g. a rendering's error).
//
// Usage (snippet: examples/snippets/bluenoise_metrics.cpp):
//
//     #include "prism/bluenoise/metrics.hpp"
//     prism::bluenoise::GrayImage image{2, 1, 8, {0, 255}};         // width, height, bits, values
//     bool uniform = prism::bluenoise::histogramUniform(image);     // levels as even as N allows
//     double lf = prism::bluenoise::lowFrequencyPowerRatio(image);  // white noise ~ 1, blue << 1
//     double fast = prism::bluenoise::filteredErrorSigma1(image);   // white noise ~ 0.114
//     double aniso = prism::bluenoise::anisotropyDb(image);         // white noise ~ 0 dB
//     std::vector<prism::bluenoise::SpectrumRing> rings = prism::bluenoise::radialPowerSpectrum(image);
//
// Definitions (docs/bluenoise.md):
// - histogramUniform: the 256 levels (value >> (bits - 8)) each occur floor(N/256) or
//   floor(N/256)+1 times; when N is a multiple of 256 this means exactly N/256 times.
// - Power spectrum: |DFT(v - mean)|^2 of the values scaled to [0, 1], frequency
//   f = (kx/W, ky/H) cycles/pixel with kx, ky wrapped to (-W/2, W/2], (-H/2, H/2].
// - lowFrequencyPowerRatio: mean power over 0 < |f| < 1/8 divided by the mean power over
//   all f != 0, which is the expected power of white noise with the same variance
//   (Parseval). 0 when the image is constant or has no such frequency.
// - filteredErrorSigma1 (the FAST metric, Donnelly et al. 2024): for every level
//   t = 0..255 the error e = [level < t] - t/256 is filtered by a normalised toroidal
//   Gaussian of sigma 1 pixel (radius 4); the result is the RMS over all pixels and levels.
// - radialPowerSpectrum: rings of width 1/max(W,H) cycles/pixel, power divided by the
//   mean non-DC power (white noise ~ 1).
// - anisotropyDb: 10 log10 of the mean over rings (>= 2 frequencies, mean > 0) of
//   variance / mean^2 of the power in the ring; 0 when no ring qualifies.
// Every function is finite for every input, including 1x1 and constant images.
#pragma once

#include <cstdint>
#include <vector>

namespace prism::bluenoise {

struct GrayImage {
    int width = 0;
    int height = 0;
    int bits = 8;                       // 8 or 16
    std::vector<std::uint16_t> values;  // row-major, row 0 at the top

    std::size_t size() const { return values.size(); }
};

struct SpectrumRing {
    double frequency = 0.0;  // ring centre, cycles per pixel
    double power = 0.0;      // mean power / mean non-DC power
    int count = 0;           // frequencies in the ring
};

struct MaskMetrics {
    bool histogramUniform = false;
    double lowFrequencyPowerRatio = 0.0;
    double filteredErrorSigma1 = 0.0;
    double anisotropyDb = 0.0;
};

bool histogramUniform(const GrayImage& image);
double lowFrequencyPowerRatio(const GrayImage& image);
double filteredErrorSigma1(const GrayImage& image);
double anisotropyDb(const GrayImage& image);
std::vector<SpectrumRing> radialPowerSpectrum(const GrayImage& image);
MaskMetrics measureMask(const GrayImage& image);

// The same spectral metrics for real-valued images (e.g. a rendering's error).
struct RealImage {
    int width = 0;
    int height = 0;
    std::vector<double> values;
};
double lowFrequencyPowerRatio(const RealImage& image);
std::vector<SpectrumRing> radialPowerSpectrum(const RealImage& image);

// Toroidal Gaussian blur (normalised, radius ceil(4 sigma)); sigma > 0.
RealImage gaussianBlur(const RealImage& image, double sigma);

// A white-noise image: each value uniform in 0..2^bits-1 from the seed.
GrayImage whiteNoiseImage(int width, int height, int bits, std::uint64_t seed);

}  // namespace prism::bluenoise
