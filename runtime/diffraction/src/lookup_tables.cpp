// Lookup tables for the GPU paths and their CPU emulation (see lookup_tables.hpp).
#include "prism/diffraction/lookup_tables.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <vector>

namespace prism::diffraction {
namespace {

using Complex = std::complex<double>;

// Runs rowBand(first, last) over [0, rows) in contiguous bands, one per hardware thread (at
// most 16). Each texel depends on its own row only, so the tables are bit-identical for every
// thread count.
template <class RowBand>
void forEachRowBand(int rows, RowBand rowBand) {
    const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::min(16, rows));
    if (threads <= 1) {
        rowBand(0, rows);
        return;
    }
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(threads - 1));
    for (int t = 1; t < threads; ++t) workers.emplace_back(rowBand, rows * t / threads, rows * (t + 1) / threads);
    rowBand(0, rows / threads);
    for (auto& w : workers) w.join();
}

// GL_LINEAR + GL_CLAMP_TO_EDGE lookup of `channels` floats at coordinate x (texture units, the
// texel grid maps [-extent, extent] with texel i centred at (i - S/2) * 2 extent / S).
struct Bilinear {
    int i0, i1, j0, j1;
    double fx, fy;
};

Bilinear bilinearAt(double x, double y, double extent, int size) {
    const double cell = 2.0 * extent / size;
    const double tx = x / cell + size / 2.0, ty = y / cell + size / 2.0;  // texel-centre units
    const double fx0 = std::floor(tx), fy0 = std::floor(ty);
    const auto clampIndex = [size](double i) { return static_cast<int>(std::min(std::max(i, 0.0), size - 1.0)); };
    return {clampIndex(fx0), clampIndex(fx0 + 1.0), clampIndex(fy0), clampIndex(fy0 + 1.0), tx - fx0, ty - fy0};
}

template <int Channels>
double fetch(const std::vector<float>& texels, int size, int layer, int i, int j, int channel) {
    return texels[((static_cast<std::size_t>(layer) * size + j) * size + i) * Channels + channel];
}

template <int Channels>
double sample(const std::vector<float>& texels, int size, int layer, const Bilinear& b, int channel) {
    const double a = fetch<Channels>(texels, size, layer, b.i0, b.j0, channel);
    const double c = fetch<Channels>(texels, size, layer, b.i1, b.j0, channel);
    const double d = fetch<Channels>(texels, size, layer, b.i0, b.j1, channel);
    const double e = fetch<Channels>(texels, size, layer, b.i1, b.j1, channel);
    return (a * (1 - b.fx) + c * b.fx) * (1 - b.fy) + (d * (1 - b.fx) + e * b.fx) * b.fy;
}

Complex sampleSpectral(const SpectralTables& t, int n, double fx, double fy) {
    const Bilinear b = bilinearAt(fx, fy, t.frequencyExtent, t.size);
    return {sample<2>(t.texels, t.size, n, b, 0), sample<2>(t.texels, t.size, n, b, 1)};
}

LinearRgb scale(LinearRgb c, double s) {
    return {c.r * s, c.g * s, c.b * s};
}

}  // namespace

SpectralTables buildSpectralTables(const StamBrdf& brdf, const TableOptions& options) {
    if (brdf.path() != StamBrdf::Path::Taylor) throw std::invalid_argument("lookup tables need a Taylor-path StamBrdf");
    if (options.size < 8 || options.size > 2048) throw std::invalid_argument("table size must be in 8..2048");
    SpectralTables t;
    t.size = options.size;
    t.terms = brdf.terms();
    t.heightScaleNm = maxAbsHeight(brdf.field());
    if (t.heightScaleNm == 0.0) t.heightScaleNm = 1.0;  // a mirror: only H_0
    t.frequencyExtent = 2.0 / kLambdaMinNm;
    for (const SpectralWeight& w : spectralWeights(options.wavelengthStepNm)) {
        t.wavelengths.push_back({w.wavelengthNm, xyzToLinearSrgb(w.xyz)});
    }
    const std::size_t layer = static_cast<std::size_t>(t.size) * t.size * 2;
    t.texels.resize(layer * (t.terms + 1));
    const double cell = 2.0 * t.frequencyExtent / t.size;
    forEachRowBand(t.size, [&](int firstRow, int lastRow) {
        for (int n = 0; n <= t.terms; ++n) {
            const double norm = std::pow(t.heightScaleNm, -n);
            const Spectrum& spectrum = brdf.taylor().terms[n];
            for (int j = firstRow; j < lastRow; ++j) {
                for (int i = 0; i < t.size; ++i) {
                    const Complex h =
                        norm * spectrum.evaluate((i - t.size / 2) * cell, (j - t.size / 2) * cell, brdf.window());
                    float* texel = &t.texels[n * layer + (static_cast<std::size_t>(j) * t.size + i) * 2];
                    texel[0] = static_cast<float>(h.real());
                    texel[1] = static_cast<float>(h.imag());
                }
            }
        }
    });
    return t;
}

IntegratedTables buildIntegratedTables(const SpectralTables& a) {
    IntegratedTables t;
    t.size = a.size;
    t.terms = a.terms;
    const int layers = 2 * a.terms + 1;
    const std::size_t layer = static_cast<std::size_t>(t.size) * t.size * 3;
    t.texels.assign(layer * layers, 0.0f);
    const double cell = 2.0 * kIntegratedExtent / t.size;
    forEachRowBand(t.size, [&](int firstRow, int lastRow) {
        std::vector<Complex> b(static_cast<std::size_t>(a.terms) + 1);
        std::vector<double> sums(static_cast<std::size_t>(layers) * 3);
        for (int j = firstRow; j < lastRow; ++j) {
            for (int i = 0; i < t.size; ++i) {
                const double u = (i - t.size / 2) * cell, v = (j - t.size / 2) * cell;
                std::fill(sums.begin(), sums.end(), 0.0);
                for (const WavelengthRgb& wl : a.wavelengths) {
                    const double ks = 2.0 * std::numbers::pi / wl.wavelengthNm * a.heightScaleNm;
                    Complex factor{1.0, 0.0};
                    for (int n = 0; n <= a.terms; ++n) {
                        if (n > 0) factor *= Complex{0.0, ks / n};
                        b[n] = factor * sampleSpectral(a, n, u / wl.wavelengthNm, v / wl.wavelengthNm);
                    }
                    bool any = false;
                    for (const Complex& c : b) any = any || c != Complex{0.0, 0.0};
                    if (!any) continue;  // outside every window: nothing to add (most texels of a 1-row field)
                    // Layer s = n + m sums Re(b_n conj(b_m)); the (n, m) and (m, n) terms are equal
                    // (Re z = Re conj z), so each pair off the diagonal is taken once, twice.
                    for (int n = 0; n <= a.terms; ++n) {
                        for (int m = n; m <= a.terms; ++m) {
                            const double re = (m == n ? 1.0 : 2.0) * (b[n] * std::conj(b[m])).real();
                            double* s = &sums[static_cast<std::size_t>(n + m) * 3];
                            s[0] += re * wl.weight.r;
                            s[1] += re * wl.weight.g;
                            s[2] += re * wl.weight.b;
                        }
                    }
                }
                for (int s = 0; s < layers; ++s) {
                    float* texel = &t.texels[s * layer + (static_cast<std::size_t>(j) * t.size + i) * 3];
                    for (int c = 0; c < 3; ++c)
                        texel[c] = static_cast<float>(sums[static_cast<std::size_t>(s) * 3 + c]);
                }
            }
        }
    });
    return t;
}

LinearRgb shadeSpectral(const SpectralTables& t, Direction wi, Direction wr) {
    const StamGeometry g = stamGeometry(wi, wr);
    LinearRgb rgb;
    if (g.factor == 0.0) return rgb;
    for (const WavelengthRgb& wl : t.wavelengths) {
        const double a = 2.0 * std::numbers::pi / wl.wavelengthNm * g.w * t.heightScaleNm;
        Complex factor{1.0, 0.0}, p{0.0, 0.0};
        for (int n = 0; n <= t.terms; ++n) {
            if (n > 0) factor *= Complex{0.0, a / n};
            p += factor * sampleSpectral(t, n, g.u / wl.wavelengthNm, g.v / wl.wavelengthNm);
        }
        const double power = std::norm(p);
        rgb = {rgb.r + power * wl.weight.r, rgb.g + power * wl.weight.g, rgb.b + power * wl.weight.b};
    }
    return scale(rgb, g.factor);
}

LinearRgb shadeIntegrated(const IntegratedTables& t, Direction wi, Direction wr) {
    const StamGeometry g = stamGeometry(wi, wr);
    LinearRgb rgb;
    if (g.factor == 0.0) return rgb;
    const Bilinear b = bilinearAt(g.u, g.v, kIntegratedExtent, t.size);
    double wPower = 1.0;
    for (int s = 0; s <= 2 * t.terms; ++s) {
        rgb = {rgb.r + wPower * sample<3>(t.texels, t.size, s, b, 0),
               rgb.g + wPower * sample<3>(t.texels, t.size, s, b, 1),
               rgb.b + wPower * sample<3>(t.texels, t.size, s, b, 2)};
        wPower *= g.w;
    }
    return scale(rgb, g.factor);
}

VolumeTables buildVolumeTables(const IntegratedTables& b, int slices) {
    if (slices < 2 || slices > 256) throw std::invalid_argument("volume slices must be in 2..256");
    VolumeTables t;
    t.size = b.size;
    t.slices = slices;
    const std::size_t texels = static_cast<std::size_t>(b.size) * b.size;
    t.texels.assign(texels * 3 * slices, 0.0f);
    for (int k = 0; k < slices; ++k) {
        const double w = -2.0 + 2.0 * k / (slices - 1);
        for (std::size_t i = 0; i < texels; ++i) {
            double rgb[3] = {0.0, 0.0, 0.0};
            double wPower = 1.0;
            for (int s = 0; s <= 2 * b.terms; ++s) {
                for (int c = 0; c < 3; ++c) rgb[c] += wPower * b.texels[(s * texels + i) * 3 + c];
                wPower *= w;
            }
            for (int c = 0; c < 3; ++c) t.texels[(k * texels + i) * 3 + c] = static_cast<float>(rgb[c]);
        }
    }
    return t;
}

LinearRgb shadeVolume(const VolumeTables& t, Direction wi, Direction wr) {
    const StamGeometry g = stamGeometry(wi, wr);
    LinearRgb rgb;
    if (g.factor == 0.0) return rgb;
    const Bilinear b = bilinearAt(g.u, g.v, kIntegratedExtent, t.size);
    // Along w: slice centres at k = (w + 2) / 2 * (K - 1), clamped like GL_CLAMP_TO_EDGE.
    const double z = std::min(std::max((g.w + 2.0) / 2.0 * (t.slices - 1), 0.0), t.slices - 1.0);
    const int k0 = std::min(static_cast<int>(std::floor(z)), t.slices - 1), k1 = std::min(k0 + 1, t.slices - 1);
    const double fz = z - k0;
    const double c0[3] = {sample<3>(t.texels, t.size, k0, b, 0), sample<3>(t.texels, t.size, k0, b, 1),
                          sample<3>(t.texels, t.size, k0, b, 2)};
    const double c1[3] = {sample<3>(t.texels, t.size, k1, b, 0), sample<3>(t.texels, t.size, k1, b, 1),
                          sample<3>(t.texels, t.size, k1, b, 2)};
    rgb = {c0[0] * (1 - fz) + c1[0] * fz, c0[1] * (1 - fz) + c1[1] * fz, c0[2] * (1 - fz) + c1[2] * fz};
    return scale(rgb, g.factor);
}

LinearRgb shadeReference(const StamBrdf& brdf, Direction wi, Direction wr, const std::vector<SpectralWeight>& weights) {
    return xyzToLinearSrgb(brdf.xyz(wi, wr, weights));
}

TableUniforms tableUniforms(const SpectralTables& t) {
    return {.path = 0,
            .size = t.size,
            .extent = t.frequencyExtent,
            .terms = t.terms,
            .heightScaleNm = t.heightScaleNm,
            .wavelengthCount = static_cast<int>(t.wavelengths.size())};
}

TableUniforms tableUniforms(const IntegratedTables& t) {
    return {.path = 1, .size = t.size, .extent = kIntegratedExtent, .terms = t.terms};
}

TableUniforms tableUniforms(const VolumeTables& t) {
    return {.path = 2, .size = t.size, .extent = kIntegratedExtent, .slices = t.slices};
}

std::vector<float> wavelengthTexels(const SpectralTables& t) {
    std::vector<float> row;
    for (const WavelengthRgb& w : t.wavelengths)
        row.insert(row.end(), {static_cast<float>(w.weight.r), static_cast<float>(w.weight.g),
                               static_cast<float>(w.weight.b), static_cast<float>(w.wavelengthNm)});
    return row;
}

std::vector<float> rgbaTexels(const std::vector<float>& rgb) {
    std::vector<float> rgba;
    rgba.reserve(rgb.size() / 3 * 4);
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 1.0f});
    return rgba;
}

}  // namespace prism::diffraction
