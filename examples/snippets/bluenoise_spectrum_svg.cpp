// The usage example of prism/bluenoise/spectrum_svg.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/bluenoise/spectrum_svg.hpp"
// [/snippet]

int main() {
    // [snippet]
    std::vector<prism::bluenoise::SpectrumRing> rings = {{0.1, 0.2, 4}, {0.2, 1.1, 8}};
    std::string svg = prism::bluenoise::spectrumSvg({{"void-and-cluster 64x64", rings}});
    prism::bluenoise::PlotSeries s{"white", {{1, 0.3}, {4, 0.15}}};
    std::string plot = prism::bluenoise::linePlotSvg("frames", "RMS error", {s}, true);
    // [/snippet]
    auto has = [](const std::string& text, const char* part) { return text.find(part) != std::string::npos; };
    return has(svg, "<svg") && has(svg, "</svg>") && has(svg, "void-and-cluster 64x64") && has(plot, "<svg") &&
                   has(plot, "RMS error") && has(plot, "frames") && has(plot, "white")
               ? 0
               : 1;
}
