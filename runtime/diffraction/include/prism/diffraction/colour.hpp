// Spectral colour for the diffraction shader: CIE 1931 2-degree colour matching functions and the
// D65 spectrum (from Debian's colord-data, read at build time), wavelength grids of 1, 2, 5, 10 or
// 20 nm over 380-780 nm with D65 inside the integral, and XYZ -> linear sRGB (IEC 61966-2-1).
//
// Usage (snippet: examples/snippets/diffraction_colour.cpp):
//
//     #include "prism/diffraction/colour.hpp"
//     using namespace prism::diffraction;
//     std::vector<SpectralWeight> grid = spectralWeights(5);       // 81 wavelengths
//     Xyz white{};                                                 // a flat reflectance of 1
//     for (const SpectralWeight& s : grid) white = white + s.xyz;  // = D65 white, Y = 1
//     LinearRgb rgb = xyzToLinearSrgb(white);                      // ~ (1, 1, 1)
//
// A spectral reflectance rho(lambda) lit by D65 has XYZ = sum_i rho(lambda_i) * grid[i].xyz:
// each weight is D65(lambda) cmf(lambda) dlambda / sum(D65 ybar dlambda), so white has Y = 1.
// Steps of 1 and 2 nm interpolate the 5 nm tables linearly.
#pragma once

#include <string>
#include <vector>

namespace prism::diffraction {

struct Xyz {
    double x = 0, y = 0, z = 0;
};
inline Xyz operator+(Xyz a, Xyz b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Xyz operator*(double s, Xyz a) {
    return {s * a.x, s * a.y, s * a.z};
}

struct LinearRgb {
    double r = 0, g = 0, b = 0;
};

inline constexpr double kLambdaMinNm = 380.0;
inline constexpr double kLambdaMaxNm = 780.0;

// The colour matching functions at a wavelength (linear between the 5 nm samples; 0 outside
// the table's 360-830 nm).
Xyz colourMatching(double wavelengthNm);
// The D65 relative spectral power (1 at 560 nm) at a wavelength (linear between samples).
double d65(double wavelengthNm);
// Where the tables came from: "path (sha256 ...)" of the colord-data files.
std::string cmfSource();
std::string d65Source();

// True for the supported steps 1, 2, 5, 10 and 20 nm.
bool isSupportedWavelengthStep(int stepNm);

struct SpectralWeight {
    double wavelengthNm;
    Xyz xyz;  // D65 * cmf * dlambda, normalised so that sum(y) = 1
};
// Wavelengths 380, 380+step, ..., 780 with their weights. Throws std::invalid_argument for an
// unsupported step.
std::vector<SpectralWeight> spectralWeights(int stepNm);

// IEC 61966-2-1 (sRGB) XYZ -> linear RGB; D65 white (0.9505, 1, 1.089) maps to (1, 1, 1).
LinearRgb xyzToLinearSrgb(Xyz xyz);
// The sRGB transfer function (linear -> encoded), for 8-bit output; clamps to [0, 1].
double srgbEncode(double linear);

}  // namespace prism::diffraction
