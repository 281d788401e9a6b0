// SVG line plots: radially averaged power spectra (with white noise = 1 as reference) and
// general x/y series (convergence plots of docs/bluenoise.md).
//
// Usage (snippet: examples/snippets/bluenoise_spectrum_svg.cpp):
//
//     #include "prism/bluenoise/spectrum_svg.hpp"
//     std::vector<prism::bluenoise::SpectrumRing> rings = {{0.1, 0.2, 4}, {0.2, 1.1, 8}};
//     std::string svg = prism::bluenoise::spectrumSvg({{"void-and-cluster 64x64", rings}});
//     prism::bluenoise::PlotSeries s{"white", {{1, 0.3}, {4, 0.15}}};
//     std::string plot = prism::bluenoise::linePlotSvg("frames", "RMS error", {s}, true);
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "prism/bluenoise/metrics.hpp"

namespace prism::bluenoise {

struct NamedSpectrum {
    std::string name;
    std::vector<SpectrumRing> rings;
};

struct PlotSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;
};

// Power against frequency 0..0.71 cycles/pixel, a dashed line at 1 for white noise.
std::string spectrumSvg(const std::vector<NamedSpectrum>& spectra);

// x/y lines, log-log when `logAxes` (non-positive values are skipped there).
std::string linePlotSvg(const std::string& xLabel, const std::string& yLabel, const std::vector<PlotSeries>& series,
                        bool logAxes);

}  // namespace prism::bluenoise
