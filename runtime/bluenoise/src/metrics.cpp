// Mask metrics: histogram, DFT power spectrum (plain double-precision DFT), FAST error.
#include "prism/bluenoise/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "prism/bluenoise/random.hpp"

namespace prism::bluenoise {
namespace {

using Complex = std::complex<double>;

void checkShape(int width, int height, std::size_t count, const char* what) {
    if (width < 1 || height < 1 || static_cast<std::size_t>(width) * static_cast<std::size_t>(height) != count)
        throw std::invalid_argument(std::string(what) + ": image of " + std::to_string(width) + "x" +
                                    std::to_string(height) + " with " + std::to_string(count) + " values");
}

void checkGray(const GrayImage& image) {
    checkShape(image.width, image.height, image.values.size(), "prism::bluenoise metrics");
    if (image.bits != 8 && image.bits != 16)
        throw std::invalid_argument("prism::bluenoise metrics: bits must be 8 or 16, got " +
                                    std::to_string(image.bits));
}

RealImage toReal(const GrayImage& image) {
    checkGray(image);
    RealImage out{image.width, image.height, std::vector<double>(image.size())};
    const double scale = 1.0 / static_cast<double>(1 << image.bits);
    for (std::size_t i = 0; i < image.size(); ++i) out.values[i] = image.values[i] * scale;
    return out;
}

// In-place DFT of `n` values spaced `stride` apart, with a cos/sin table of length n.
void dft(Complex* data, int n, int stride, const std::vector<Complex>& twiddle, std::vector<Complex>& scratch) {
    scratch.assign(static_cast<std::size_t>(n), Complex{});
    for (int k = 0; k < n; ++k) {
        Complex sum{};
        std::size_t index = 0;  // (j * k) mod n
        for (int j = 0; j < n; ++j) {
            sum += data[static_cast<std::ptrdiff_t>(j) * stride] * twiddle[index];
            index += static_cast<std::size_t>(k);
            if (index >= static_cast<std::size_t>(n)) index -= static_cast<std::size_t>(n);
        }
        scratch[static_cast<std::size_t>(k)] = sum;
    }
    for (int k = 0; k < n; ++k) data[static_cast<std::ptrdiff_t>(k) * stride] = scratch[static_cast<std::size_t>(k)];
}

std::vector<Complex> twiddles(int n) {
    std::vector<Complex> t(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) t[static_cast<std::size_t>(j)] = std::polar(1.0, -2.0 * std::numbers::pi * j / n);
    return t;
}

// |DFT(v - mean)|^2, row-major like the image.
std::vector<double> powerSpectrum(const RealImage& image) {
    checkShape(image.width, image.height, image.values.size(), "prism::bluenoise spectrum");
    const int w = image.width, h = image.height;
    double mean = 0.0;
    for (double v : image.values) mean += v;
    mean /= static_cast<double>(image.values.size());
    std::vector<Complex> grid(image.values.size());
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = image.values[i] - mean;
    std::vector<Complex> scratch;
    const std::vector<Complex> tw = twiddles(w), th = twiddles(h);
    for (int y = 0; y < h; ++y) dft(grid.data() + static_cast<std::ptrdiff_t>(y) * w, w, 1, tw, scratch);
    for (int x = 0; x < w; ++x) dft(grid.data() + x, h, w, th, scratch);
    std::vector<double> power(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) power[i] = std::norm(grid[i]);
    return power;
}

// Signed frequency index of DFT bin k of length n, in (-n/2, n/2].
int signedIndex(int k, int n) {
    return k > n / 2 ? k - n : k;
}

double frequencyOf(int kx, int ky, int w, int h) {
    const double fx = static_cast<double>(signedIndex(kx, w)) / w;
    const double fy = static_cast<double>(signedIndex(ky, h)) / h;
    return std::sqrt(fx * fx + fy * fy);
}

double meanNonDcPower(const std::vector<double>& power) {
    if (power.size() < 2) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 1; i < power.size(); ++i) sum += power[i];
    return sum / static_cast<double>(power.size() - 1);
}

struct RingSums {
    std::vector<double> sum, sumSquares;
    std::vector<int> count;
};

RingSums ringSums(const std::vector<double>& power, int w, int h) {
    const int side = std::max(w, h);
    const int rings = static_cast<int>(std::ceil(side * std::numbers::sqrt2 / 2.0)) + 2;
    RingSums r{std::vector<double>(static_cast<std::size_t>(rings)),
               std::vector<double>(static_cast<std::size_t>(rings)), std::vector<int>(static_cast<std::size_t>(rings))};
    for (int ky = 0; ky < h; ++ky)
        for (int kx = 0; kx < w; ++kx) {
            if (kx == 0 && ky == 0) continue;
            const int ring = static_cast<int>(std::lround(frequencyOf(kx, ky, w, h) * side));
            const double p =
                power[static_cast<std::size_t>(ky) * static_cast<std::size_t>(w) + static_cast<std::size_t>(kx)];
            r.sum[static_cast<std::size_t>(ring)] += p;
            r.sumSquares[static_cast<std::size_t>(ring)] += p * p;
            ++r.count[static_cast<std::size_t>(ring)];
        }
    return r;
}

std::vector<SpectrumRing> rings(const std::vector<double>& power, int w, int h) {
    const double reference = meanNonDcPower(power);
    const RingSums sums = ringSums(power, w, h);
    const int side = std::max(w, h);
    std::vector<SpectrumRing> out;
    for (std::size_t i = 0; i < sums.count.size(); ++i) {
        if (sums.count[i] == 0) continue;
        const double mean = sums.sum[i] / sums.count[i];
        out.push_back({static_cast<double>(i) / side, reference > 0.0 ? mean / reference : 0.0, sums.count[i]});
    }
    return out;
}

double lowFrequencyRatio(const std::vector<double>& power, int w, int h) {
    const double reference = meanNonDcPower(power);
    if (!(reference > 0.0)) return 0.0;
    double sum = 0.0;
    int count = 0;
    for (int ky = 0; ky < h; ++ky)
        for (int kx = 0; kx < w; ++kx) {
            if (kx == 0 && ky == 0) continue;
            if (frequencyOf(kx, ky, w, h) >= 0.125) continue;
            sum += power[static_cast<std::size_t>(ky) * static_cast<std::size_t>(w) + static_cast<std::size_t>(kx)];
            ++count;
        }
    return count > 0 ? (sum / count) / reference : 0.0;
}

// Normalised 1D Gaussian weights for offsets -radius..radius.
std::vector<double> gaussianWeights(double sigma, int radius) {
    std::vector<double> w(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int d = -radius; d <= radius; ++d)
        sum += w[static_cast<std::size_t>(d + radius)] = std::exp(-0.5 * d * d / (sigma * sigma));
    for (double& v : w) v /= sum;
    return w;
}

int wrap(int v, int n) {
    return ((v % n) + n) % n;
}

}  // namespace

bool histogramUniform(const GrayImage& image) {
    checkGray(image);
    std::vector<std::size_t> counts(256, 0);
    for (std::uint16_t v : image.values) ++counts[static_cast<std::size_t>(v >> (image.bits - 8))];
    const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
    return *hi - *lo <= 1;
}

double lowFrequencyPowerRatio(const RealImage& image) {
    return lowFrequencyRatio(powerSpectrum(image), image.width, image.height);
}
double lowFrequencyPowerRatio(const GrayImage& image) {
    return lowFrequencyPowerRatio(toReal(image));
}

std::vector<SpectrumRing> radialPowerSpectrum(const RealImage& image) {
    return rings(powerSpectrum(image), image.width, image.height);
}
std::vector<SpectrumRing> radialPowerSpectrum(const GrayImage& image) {
    return radialPowerSpectrum(toReal(image));
}

double anisotropyDb(const GrayImage& image) {
    const RealImage real = toReal(image);
    const RingSums sums = ringSums(powerSpectrum(real), real.width, real.height);
    double total = 0.0;
    int used = 0;
    for (std::size_t i = 0; i < sums.count.size(); ++i) {
        if (sums.count[i] < 2) continue;
        const double mean = sums.sum[i] / sums.count[i];
        if (!(mean > 0.0)) continue;
        const double variance = std::max(0.0, sums.sumSquares[i] / sums.count[i] - mean * mean);
        total += variance / (mean * mean);
        ++used;
    }
    if (used == 0) return 0.0;
    return 10.0 * std::log10(std::max(total / used, 1e-12));
}

double filteredErrorSigma1(const GrayImage& image) {
    checkGray(image);
    const int w = image.width, h = image.height;
    const int radius = 4;
    const std::vector<double> g = gaussianWeights(1.0, radius);
    // Pixels by level, so level t's binary image is level t-1's plus one set of splats.
    std::vector<std::vector<int>> byLevel(256);
    for (std::size_t i = 0; i < image.size(); ++i)
        byLevel[static_cast<std::size_t>(image.values[i] >> (image.bits - 8))].push_back(static_cast<int>(i));
    std::vector<double> blurred(image.size(), 0.0);  // G * [level < t]
    double sumSquares = 0.0;
    for (int t = 0; t < 256; ++t) {
        if (t > 0)
            for (int index : byLevel[static_cast<std::size_t>(t - 1)]) {
                const int x = index % w, y = index / w;
                for (int dy = -radius; dy <= radius; ++dy) {
                    const std::size_t row = static_cast<std::size_t>(wrap(y + dy, h)) * static_cast<std::size_t>(w);
                    const double gy = g[static_cast<std::size_t>(dy + radius)];
                    for (int dx = -radius; dx <= radius; ++dx)
                        blurred[row + static_cast<std::size_t>(wrap(x + dx, w))] +=
                            gy * g[static_cast<std::size_t>(dx + radius)];
                }
            }
        const double target = t / 256.0;
        for (double b : blurred) sumSquares += (b - target) * (b - target);
    }
    return std::sqrt(sumSquares / (256.0 * static_cast<double>(image.size())));
}

MaskMetrics measureMask(const GrayImage& image) {
    return {histogramUniform(image), lowFrequencyPowerRatio(image), filteredErrorSigma1(image), anisotropyDb(image)};
}

RealImage gaussianBlur(const RealImage& image, double sigma) {
    checkShape(image.width, image.height, image.values.size(), "prism::bluenoise::gaussianBlur");
    if (!std::isfinite(sigma) || sigma <= 0.0)
        throw std::invalid_argument("prism::bluenoise::gaussianBlur: sigma must be finite and > 0");
    const int radius = static_cast<int>(std::ceil(4.0 * sigma));
    const std::vector<double> g = gaussianWeights(sigma, radius);
    const int w = image.width, h = image.height;
    RealImage tmp{w, h, std::vector<double>(image.values.size(), 0.0)};
    RealImage out = tmp;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int d = -radius; d <= radius; ++d)
                s += g[static_cast<std::size_t>(d + radius)] *
                     image.values[static_cast<std::size_t>(y * w + wrap(x + d, w))];
            tmp.values[static_cast<std::size_t>(y * w + x)] = s;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int d = -radius; d <= radius; ++d)
                s += g[static_cast<std::size_t>(d + radius)] *
                     tmp.values[static_cast<std::size_t>(wrap(y + d, h) * w + x)];
            out.values[static_cast<std::size_t>(y * w + x)] = s;
        }
    return out;
}

GrayImage whiteNoiseImage(int width, int height, int bits, std::uint64_t seed) {
    GrayImage image{width, height, bits,
                    std::vector<std::uint16_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))};
    checkGray(image);
    SplitMix64 rng(seed);
    for (std::uint16_t& v : image.values) v = static_cast<std::uint16_t>(rng.next() >> (64 - bits));
    return image;
}

}  // namespace prism::bluenoise
