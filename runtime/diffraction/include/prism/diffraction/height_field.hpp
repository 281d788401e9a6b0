// Surface height fields for the diffraction shader (nanometres throughout): a sinusoidal grating,
// a blazed (sawtooth) grating, CD-like tracks at 1600 nm pitch, a quasi-periodic snake-skin
// ridge field and a user's 8- or 16-bit grey PNG. All are periodic patches: the spectrum code
// treats the patch as one tile of an infinite periodic surface (then windows it, spectrum.hpp).
//
// Usage (snippet: examples/snippets/diffraction_height_field.cpp):
//
//     #include "prism/diffraction/height_field.hpp"
//     using namespace prism::diffraction;
//     HeightField grating = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
//     subtractMean(grating);                // lowers k w h_max; |P|^2 is unchanged
//     double hMax = maxAbsHeight(grating);  // 150 nm, feeds termsForTolerance()
//
// One-row fields (the gratings) are constant along y.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace prism::diffraction {

struct HeightField {
    int width = 0;                  // samples along x
    int height = 0;                 // samples along y (1 for a field constant along y)
    double pixelNm = 1.0;           // sample spacing along x and y
    std::vector<double> heightsNm;  // row-major, width * height
    double at(int x, int y) const { return heightsNm[static_cast<std::size_t>(y) * width + x]; }
    double widthNm() const { return width * pixelNm; }
    double heightNm() const { return height * pixelNm; }
};

struct GratingParams {
    double periodNm = 2500.0;
    double amplitudeNm = 150.0;  // sinusoid: h = A sin(2 pi x / d); blazed: h rises 0..2A per period
    int periods = 64;            // periods in the patch
    int samplesPerPeriod = 32;

    bool operator==(const GratingParams&) const = default;
};
// Throw std::invalid_argument naming the bad parameter (period <= 0, amplitude < 0, ...).
HeightField sinusoidGrating(const GratingParams& params);
HeightField blazedGrating(const GratingParams& params);

struct TrackParams {
    double pitchNm = 1600.0;    // CD track pitch
    double pitDepthNm = 110.0;  // about lambda/4 of a CD laser in polycarbonate
    double pitWidthNm = 500.0;
    int size = 256;  // samples per side
    double pixelNm = 100.0;
    std::uint32_t seed = 1;  // RNG seed of the pit lengths

    bool operator==(const TrackParams&) const = default;
};
// Tracks run along y; pits of random length (0.9-3.3 um) along each track.
HeightField cdTracks(const TrackParams& params);

struct RidgeParams {
    double spacingNm = 1400.0;  // mean ridge spacing
    double heightNm = 120.0;    // ridge height
    double wavinessNm = 300.0;  // lateral meander of each ridge
    int size = 256;
    double pixelNm = 100.0;
    std::uint32_t seed = 1;  // RNG seed of the meanders and spacing jitter

    bool operator==(const RidgeParams&) const = default;
};
// Quasi-periodic finger-like ridges (after the Elaphe and Xenopeltis sheds of the diffraction thesis).
HeightField snakeRidges(const RidgeParams& params);

// A grey (or RGB: the first channel) 8- or 16-bit PNG: height = value / max * heightScaleNm.
// Throws std::runtime_error "path: error: ..." when the file cannot be read or decoded.
HeightField loadHeightFieldPng(const std::string& path, double nmPerPixel, double heightScaleNm);

void subtractMean(HeightField& field);
double maxAbsHeight(const HeightField& field);

}  // namespace prism::diffraction
