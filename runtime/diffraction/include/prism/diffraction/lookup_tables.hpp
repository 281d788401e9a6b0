// The GPU shader's lookup tables, built on the CPU from a Taylor-path StamBrdf, and double-
// precision emulations of the two shader paths (what modules/diffraction/stam.glsl computes):
//   (a) spectral tables: layer n (0..N) holds H_n(f) = windowed FFT(h^n) / s^n on an S x S grid
//       of frequencies f in [-F, F]^2 cycles/nm (F = 2 / 380 nm), complex in RG, s = max |h|;
//       the shader sums P = sum_n (i k w s)^n / n! H_n(u / lambda, v / lambda) per wavelength and
//       weights |P|^2 by D65 * cmf -> linear sRGB (colour.hpp).
//   (b) integrated tables (after Dhillon et al. 2014): layer t (0..2N) holds, on (u, v) in
//       [-2, 2]^2, T_t = sum_lambda rgb(lambda) sum_{n+m=t} Re[b_n conj(b_m)], b_n =
//       (i k s)^n / n! H_n(u / lambda, v / lambda); the shader needs only rgb = sum_t w^t T_t.
//   (c) volume: path b's sum_t w^t T_t tabulated at K slices of w in [-2, 0] (a 3D RGB texture):
//       one trilinear fetch per pixel and light instead of 2N + 1.
// All times G / w^2 (stam_brdf.hpp). Texel i sits at (i - S/2) * cell, so frequency 0 is a
// texel centre; lookups are bilinear with GL's clamp-to-edge rules.
//
// Usage (snippet: examples/snippets/diffraction_lookup_tables.cpp):
//
//     #include "prism/diffraction/lookup_tables.hpp"
//     using namespace prism::diffraction;
//     StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
//     SpectralTables a = buildSpectralTables(brdf, {.size = 64, .wavelengthStepNm = 10});
//     IntegratedTables b = buildIntegratedTables(a);
//     LinearRgb viaA = shadeSpectral(a, fromAngles(30, 180), fromAngles(30, 0));
//     LinearRgb viaB = shadeIntegrated(b, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaA
//     VolumeTables c = buildVolumeTables(b, /*slices of w*/ 16);
//     LinearRgb viaC = shadeVolume(c, fromAngles(30, 180), fromAngles(30, 0));  // ~ viaB
#pragma once

#include <cstddef>
#include <vector>

#include "prism/diffraction/stam_brdf.hpp"

namespace prism::diffraction {

struct TableOptions {
    int size = 256;            // S, 8..2048
    int wavelengthStepNm = 5;  // 1, 2, 5, 10 or 20
};

struct WavelengthRgb {
    double wavelengthNm;
    LinearRgb weight;  // D65 * cmf * dlambda in linear sRGB, white -> (1, 1, 1)
};

struct SpectralTables {
    int size = 0;
    int terms = 0;                 // N; layers = N + 1
    double heightScaleNm = 0.0;    // s
    double frequencyExtent = 0.0;  // F, cycles per nm
    std::vector<WavelengthRgb> wavelengths;
    std::vector<float> texels;  // layer-major, row-major, 2 floats (re, im) per texel
    std::size_t bytes() const { return texels.size() * sizeof(float); }
};

struct IntegratedTables {
    int size = 0;
    int terms = 0;              // N; layers = 2N + 1
    std::vector<float> texels;  // layer-major, row-major, 3 floats (linear sRGB) per texel
    std::size_t bytes() const { return texels.size() * sizeof(float); }
};

struct VolumeTables {
    int size = 0;
    int slices = 0;             // K, at w_k = -2 + 2k / (K - 1)
    std::vector<float> texels;  // slice-major, row-major, 3 floats (linear sRGB) per texel
    std::size_t bytes() const { return texels.size() * sizeof(float); }
};

inline constexpr double kIntegratedExtent = 2.0;  // |u|, |v| <= 2

// Throws std::invalid_argument for an Exact-path brdf (no Taylor spectra) or bad options.
SpectralTables buildSpectralTables(const StamBrdf& brdf, const TableOptions& options);
IntegratedTables buildIntegratedTables(const SpectralTables& spectral);
// Throws std::invalid_argument for fewer than 2 or more than 256 slices.
VolumeTables buildVolumeTables(const IntegratedTables& integrated, int slices);

LinearRgb shadeSpectral(const SpectralTables& tables, Direction toLight, Direction toViewer);
LinearRgb shadeIntegrated(const IntegratedTables& tables, Direction toLight, Direction toViewer);
LinearRgb shadeVolume(const VolumeTables& tables, Direction toLight, Direction toViewer);

// What modules/diffraction/stam.glsl needs beside one path's textures: the DIFFRACTION_PATH
// variant value and its u_diffraction* scalars (the fields the path does not use stay 0).
// Both the GL and the Vulkan upload set the uniforms from this.
struct TableUniforms {
    int path = 0;  // 0 (a), 1 (b) or 2 (c)
    int size = 0;
    double extent = 0.0;         // u_diffractionExtent
    int terms = 0;               // u_diffractionTerms, paths a and b
    int slices = 0;              // u_diffractionSlices, path c
    double heightScaleNm = 0.0;  // u_diffractionHeightScale, path a
    int wavelengthCount = 0;     // u_diffractionWavelengthCount, path a
    const char* variant() const { return path == 0 ? "0" : path == 1 ? "1" : "2"; }
};
TableUniforms tableUniforms(const SpectralTables& tables);
TableUniforms tableUniforms(const IntegratedTables& tables);
TableUniforms tableUniforms(const VolumeTables& tables);

// Path a's wavelengths as one row of RGBA floats (u_diffractionWavelengths): rgb = the weight,
// a = the wavelength in nm.
std::vector<float> wavelengthTexels(const SpectralTables& tables);
// RGB texels (paths b and c) as RGBA with alpha 1, for an API that samples no RGB32F image (Vulkan).
std::vector<float> rgbaTexels(const std::vector<float>& rgb);

// The table-free reference: xyzToLinearSrgb(brdf.xyz(...)).
LinearRgb shadeReference(const StamBrdf& brdf, Direction toLight, Direction toViewer,
                         const std::vector<SpectralWeight>& weights);

}  // namespace prism::diffraction
