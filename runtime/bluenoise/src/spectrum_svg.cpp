// Small hand-written SVG line plots.
#include "prism/bluenoise/spectrum_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace prism::bluenoise {
namespace {

constexpr double kWidth = 640, kHeight = 400, kLeft = 70, kRight = 20, kTop = 20, kBottom = 50;
const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

struct Axes {
    double x0, x1, y0, y1;
    bool log;
    double px(double x) const {
        const double t =
            log ? (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) : (x - x0) / (x1 - x0);
        return kLeft + t * (kWidth - kLeft - kRight);
    }
    double py(double y) const {
        const double t =
            log ? (std::log10(y) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) : (y - y0) / (y1 - y0);
        return kHeight - kBottom - t * (kHeight - kTop - kBottom);
    }
};

std::string frame(const Axes& a, const std::string& xLabel, const std::string& yLabel) {
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) + "\" height=\"" +
                    number(kHeight) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s += "<rect x=\"" + number(kLeft) + "\" y=\"" + number(kTop) + "\" width=\"" + number(kWidth - kLeft - kRight) +
         "\" height=\"" + number(kHeight - kTop - kBottom) + "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int i = 0; i <= 4; ++i) {
        const double fx = a.log ? std::pow(10.0, std::log10(a.x0) + i * (std::log10(a.x1) - std::log10(a.x0)) / 4)
                                : a.x0 + i * (a.x1 - a.x0) / 4;
        const double fy = a.log ? std::pow(10.0, std::log10(a.y0) + i * (std::log10(a.y1) - std::log10(a.y0)) / 4)
                                : a.y0 + i * (a.y1 - a.y0) / 4;
        s += "<text x=\"" + number(a.px(fx)) + "\" y=\"" + number(kHeight - kBottom + 16) +
             "\" text-anchor=\"middle\">" + number(fx) + "</text>\n";
        s += "<text x=\"" + number(kLeft - 6) + "\" y=\"" + number(a.py(fy) + 4) + "\" text-anchor=\"end\">" +
             number(fy) + "</text>\n";
    }
    s += "<text x=\"" + number((kLeft + kWidth - kRight) / 2) + "\" y=\"" + number(kHeight - 12) +
         "\" text-anchor=\"middle\">" + escape(xLabel) + "</text>\n";
    s += "<text transform=\"translate(16," + number((kTop + kHeight - kBottom) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">" + escape(yLabel) + "</text>\n";
    return s;
}

std::string polyline(const Axes& a, const std::vector<std::pair<double, double>>& points, const char* color,
                     const char* dash) {
    std::string s = "<polyline fill=\"none\" stroke=\"" + std::string(color) + "\" stroke-width=\"1.5\"" +
                    (dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : std::string()) + " points=\"";
    for (const auto& [x, y] : points) {
        if (a.log && (x <= 0 || y <= 0)) continue;
        const double cy = std::clamp(y, a.y0, a.y1);
        s += number(a.px(x)) + "," + number(a.py(cy)) + " ";
    }
    s += "\"/>\n";
    return s;
}

std::string legend(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const double y = kTop + 16 + 16 * static_cast<double>(i);
        s += "<line x1=\"" + number(kWidth - 230) + "\" x2=\"" + number(kWidth - 205) + "\" y1=\"" + number(y - 4) +
             "\" y2=\"" + number(y - 4) + "\" stroke=\"" + (i < 6 ? kColors[i] : "black") + "\" stroke-width=\"2\"/>\n";
        s += "<text x=\"" + number(kWidth - 200) + "\" y=\"" + number(y) + "\">" + escape(names[i]) + "</text>\n";
    }
    return s;
}

}  // namespace

std::string spectrumSvg(const std::vector<NamedSpectrum>& spectra) {
    double top = 2.0;
    for (const auto& s : spectra)
        for (const auto& r : s.rings) top = std::max(top, std::isfinite(r.power) ? r.power : 0.0);
    const Axes a{0.0, 0.71, 0.0, std::ceil(top), false};
    std::string svg = frame(a, "frequency (cycles/pixel)", "radially averaged power / white");
    svg += polyline(a, {{0.0, 1.0}, {0.71, 1.0}}, "gray", "6,4");
    std::vector<std::string> names;
    for (std::size_t i = 0; i < spectra.size(); ++i) {
        std::vector<std::pair<double, double>> points;
        for (const auto& r : spectra[i].rings) points.emplace_back(r.frequency, r.power);
        svg += polyline(a, points, kColors[i % 6], nullptr);
        names.push_back(spectra[i].name);
    }
    names.push_back("white noise (expected)");
    svg += legend(names);
    svg += "</svg>\n";
    return svg;
}

std::string linePlotSvg(const std::string& xLabel, const std::string& yLabel, const std::vector<PlotSeries>& series,
                        bool logAxes) {
    double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& s : series)
        for (const auto& [x, y] : s.points) {
            if (logAxes && (x <= 0 || y <= 0)) continue;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    if (x0 > x1) x0 = 1, x1 = 2, y0 = 1, y1 = 2;
    if (x1 <= x0) x1 = x0 * 2 + 1;
    if (y1 <= y0) y1 = y0 * 2 + 1;
    if (!logAxes) y0 = std::min(0.0, y0);
    const Axes a{x0, x1, y0, y1, logAxes};
    std::string svg = frame(a, xLabel, yLabel);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < series.size(); ++i) {
        svg += polyline(a, series[i].points, kColors[i % 6], nullptr);
        names.push_back(series[i].name);
    }
    svg += legend(names);
    svg += "</svg>\n";
    return svg;
}

}  // namespace prism::bluenoise
