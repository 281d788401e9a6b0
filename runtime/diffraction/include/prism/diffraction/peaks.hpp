// Diffraction peaks of a BRDF in the plane of incidence: samples the outgoing angle theta
// (degrees from the normal, positive on the specular side, so order 0 is at +incidence), refines
// each local maximum by golden-section search to better than 0.001 deg and names its order m
// from the grating equation sin(theta) = sin(incidence) + m lambda / d.
//
// Usage (snippet: examples/snippets/diffraction_peaks.cpp):
//
//     #include "prism/diffraction/peaks.hpp"
//     using namespace prism::diffraction;
//     StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), {});
//     std::vector<Peak> peaks = findPeaks(brdf, {.incidenceDeg = 0, .wavelengthsNm = {550}, .periodNm = 2500});
//     // one peak per order, e.g. {550, -1, -12.709, 0.05...} and {550, 1, 12.709, ...}
#pragma once

#include <vector>

#include "prism/diffraction/stam_brdf.hpp"

namespace prism::diffraction {

struct Peak {
    double wavelengthNm = 0;
    int order = 0;
    double angleDeg = 0;
    double relativeIntensity = 0;  // BRDF at the peak / BRDF at the order-0 peak
};

struct PeakSearch {
    double incidenceDeg = 0;
    std::vector<double> wavelengthsNm{};
    double periodNm = 2500;  // only to name the orders
    double stepDeg = 0.02;   // sampling step before refinement
    double maxAngleDeg = 89.9;
    double minRelativeIntensity = 1e-6;  // ignore maxima below this fraction of the strongest
};

// Throws std::invalid_argument for an incidence outside [0, 89.9] deg or a bad step.
std::vector<Peak> findPeaks(const StamBrdf& brdf, const PeakSearch& search);

}  // namespace prism::diffraction
