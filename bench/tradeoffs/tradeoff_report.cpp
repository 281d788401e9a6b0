// Table, CSV, Pareto front and SVG plot of prism_bench_tradeoffs (see tradeoff_report.hpp).
#include "tradeoff_report.hpp"

#include "prism/reference/pareto.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace prism::bench {
namespace {

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string shaderColour(const std::string& shader) {
    static const std::map<std::string, std::string> colours{
        {"flat", "#1f77b4"}, {"smooth", "#2ca02c"}, {"gouraud", "#ff7f0e"}, {"phong", "#d62728"}};
    const auto it = colours.find(shader);
    return it == colours.end() ? "#7f7f7f" : it->second;
}

// Log-scale axis from lo to hi onto pixels [p0, p1].
struct LogAxis {
    double lo, hi, p0, p1;
    double operator()(double v) const {
        const double t = (std::log10(std::max(v, lo)) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
        return p0 + t * (p1 - p0);
    }
    std::vector<double> ticks() const {
        std::vector<double> out;
        for (int e = static_cast<int>(std::floor(std::log10(lo))) - 1; e <= static_cast<int>(std::ceil(std::log10(hi)));
             ++e)
            for (double m : {1.0, 2.0, 3.0, 5.0}) {
                const double v = m * std::pow(10.0, e);
                if (v >= lo * 0.999 && v <= hi * 1.001) out.push_back(v);
            }
        return out;
    }
};

// The nearest 1, 2, 3 or 5 times a power of ten at or below / above v (> 0), so that
// the axes start and end on a labelled tick.
double niceBelow(double v) {
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    double best = p;
    for (double m : {1.0, 2.0, 3.0, 5.0})
        if (m * p <= v) best = m * p;
    return best;
}

double niceAbove(double v) {
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 3.0, 5.0, 10.0})
        if (m * p >= v) return m * p;
    return 10.0 * p;
}

std::string tickLabel(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

std::string rowName(const Row& row) {
    return row.shader + " L" + std::to_string(row.level);
}

namespace {
std::vector<double> costs(const std::vector<Row>& rows) {
    std::vector<double> ms;
    for (const Row& r : rows) ms.push_back(r.medianMs);
    return ms;
}
std::vector<double> errors(const std::vector<Row>& rows, const ErrorOf& error) {
    std::vector<double> e;
    for (const Row& r : rows) e.push_back(error(r));
    return e;
}
}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<Row>& rows, const ErrorOf& error) {
    return reference::paretoFront(costs(rows), errors(rows, error));
}

std::optional<std::size_t> cheapestWithin(const std::vector<Row>& rows, const ErrorOf& error, double budget,
                                          const std::vector<std::size_t>& candidates) {
    return reference::cheapestWithin(costs(rows), errors(rows, error), budget, candidates);
}

void printTable(std::ostream& out, const std::vector<Row>& rows) {
    out << "| shader | level | triangles | median ms | min ms | median CPU ms | ref | mean err | max err | interior "
           "mean | interior max "
           "| silhouette px (mesh only + sphere only) | highlight err px | mean err vs full ref |\n"
        << "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Row& r : rows) {
        const Metrics& m = r.matched;
        out << "| " << r.shader << " | " << r.level << " | " << r.triangles << " | " << fixed(r.medianMs, 2) << " | "
            << fixed(r.minMs, 2) << " | " << fixed(r.medianCpuMs, 2) << " | " << (r.diffuseModel ? "diffuse" : "full")
            << " | " << fixed(m.union_.mean, 2) << " | " << m.union_.max << " | " << fixed(m.interior.mean, 2) << " | "
            << m.interior.max << " | " << (m.renderOnly + m.referenceOnly) << " (" << m.renderOnly << " + "
            << m.referenceOnly << ") | " << (m.highlightFound ? fixed(m.highlightError, 1) : std::string("-")) << " | "
            << fixed(r.full.union_.mean, 2) << " |\n";
    }
}

void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows, const std::vector<std::size_t>& front) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write " + path.string());
    f << "shader,level,triangles,vertices,frames,median_ms,min_ms,p25_ms,p75_ms,median_cpu_ms,reference,"
         "mean_err,max_err,interior_pixels,interior_mean_err,interior_max_err,interior_share_le2,"
         "mesh_only_px,sphere_only_px,highlight_err_px,"
         "full_mean_err,full_max_err,full_interior_mean_err,full_highlight_err_px,pareto_full\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        const Metrics& m = r.matched;
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        f << r.shader << ',' << r.level << ',' << r.triangles << ',' << r.vertices << ',' << r.frames << ','
          << fixed(r.medianMs, 3) << ',' << fixed(r.minMs, 3) << ',' << fixed(r.p25Ms, 3) << ',' << fixed(r.p75Ms, 3)
          << ',' << fixed(r.medianCpuMs, 3) << ',' << (r.diffuseModel ? "diffuse" : "full") << ','
          << fixed(m.union_.mean, 4) << ',' << m.union_.max << ',' << m.interior.pixels << ','
          << fixed(m.interior.mean, 4) << ',' << m.interior.max << ',' << fixed(m.interior.shareWithin(2), 4) << ','
          << m.renderOnly << ',' << m.referenceOnly << ','
          << (m.highlightFound ? fixed(m.highlightError, 2) : std::string()) << ',' << fixed(r.full.union_.mean, 4)
          << ',' << r.full.union_.max << ',' << fixed(r.full.interior.mean, 4) << ','
          << (r.full.highlightFound ? fixed(r.full.highlightError, 2) : std::string()) << ',' << (onFront ? 1 : 0)
          << '\n';
    }
    if (!f) throw std::runtime_error("error writing " + path.string());
}

void writeSvg(const std::filesystem::path& path, const std::vector<Row>& rows, const std::vector<std::size_t>& front,
              const std::string& subtitle) {
    if (rows.empty()) throw std::invalid_argument("writeSvg: no rows");
    const double width = 1120, height = 540;
    const double panelW = 450, panelH = 370, top = 100;
    const double lefts[2] = {80, 620};

    double tLo = INFINITY, tHi = 0, eLo = INFINITY, eHi = 0;
    for (const Row& r : rows) {
        tLo = std::min(tLo, r.medianMs);
        tHi = std::max(tHi, r.medianMs);
        for (double e : {fullError(r), matchedError(r)}) {
            eLo = std::min(eLo, std::max(e, 0.005));
            eHi = std::max(eHi, e);
        }
    }
    tLo = niceBelow(tLo / 1.1);
    tHi = niceAbove(tHi * 1.1);
    eLo = niceBelow(eLo / 1.2);
    eHi = niceAbove(eHi * 1.2);

    std::ostringstream s;
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<!-- written by prism_bench_tradeoffs: median frame time vs mean 8-bit error of flat, smooth, gouraud and "
         "phong on icospheres against the exact sphere -->\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << width / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">"
      << "Speed vs accuracy: icosphere levels per shader (labels: subdivision level)</text>\n"
      << "<text x=\"" << width / 2 << "\" y=\"44\" text-anchor=\"middle\" fill=\"#444\">" << subtitle << "</text>\n";

    // Legend.
    double lx = width / 2 - 250;
    for (const char* name : {"flat", "smooth", "gouraud", "phong"}) {
        s << "<circle cx=\"" << lx << "\" cy=\"66\" r=\"5\" fill=\"" << shaderColour(name) << "\"/>"
          << "<text x=\"" << lx + 10 << "\" y=\"70\">" << name << "</text>\n";
        lx += 90;
    }
    s << "<path d=\"M" << lx << " 66 h26\" stroke=\"black\" stroke-dasharray=\"5,3\" fill=\"none\"/>"
      << "<text x=\"" << lx + 32 << "\" y=\"70\">Pareto front</text>\n";

    const char* titles[2] = {"error against the full reference (diffuse + specular)",
                             "error against the shader's own model (flat, smooth: diffuse only)"};
    for (int panel = 0; panel < 2; ++panel) {
        const double left = lefts[panel];
        const LogAxis x{tLo, tHi, left, left + panelW};
        const LogAxis y{eLo, eHi, top + panelH, top};
        const ErrorOf err = panel == 0 ? ErrorOf(fullError) : ErrorOf(matchedError);

        s << "<g>\n<text x=\"" << left + panelW / 2 << "\" y=\"" << top - 10
          << "\" text-anchor=\"middle\" font-weight=\"bold\">" << titles[panel] << "</text>\n";
        s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << panelW << "\" height=\"" << panelH
          << "\" fill=\"none\" stroke=\"#888\"/>\n";
        for (double t : x.ticks())
            s << "<path d=\"M" << x(t) << ' ' << top << " V" << top + panelH << "\" stroke=\"#e4e4e4\"/>"
              << "<text x=\"" << x(t) << "\" y=\"" << top + panelH + 16 << "\" text-anchor=\"middle\">" << tickLabel(t)
              << "</text>\n";
        for (double e : y.ticks())
            s << "<path d=\"M" << left << ' ' << y(e) << " H" << left + panelW << "\" stroke=\"#e4e4e4\"/>"
              << "<text x=\"" << left - 6 << "\" y=\"" << y(e) + 4 << "\" text-anchor=\"end\">" << tickLabel(e)
              << "</text>\n";
        s << "<text x=\"" << left + panelW / 2 << "\" y=\"" << top + panelH + 38
          << "\" text-anchor=\"middle\">median frame time, ms (log)</text>\n"
          << "<text transform=\"translate(" << left - 48 << ' ' << top + panelH / 2
          << ") rotate(-90)\" text-anchor=\"middle\">mean abs error, 8-bit units (log)</text>\n";

        // One polyline per shader through its levels, then the points and labels.
        std::map<std::string, std::vector<std::size_t>> series;
        for (std::size_t i = 0; i < rows.size(); ++i) series[rows[i].shader].push_back(i);
        for (auto& [shader, idx] : series) {
            std::sort(idx.begin(), idx.end(),
                      [&](std::size_t a, std::size_t b) { return rows[a].level < rows[b].level; });
            s << "<polyline fill=\"none\" stroke=\"" << shaderColour(shader) << "\" stroke-opacity=\"0.45\" points=\"";
            for (std::size_t i : idx) s << fixed(x(rows[i].medianMs), 1) << ',' << fixed(y(err(rows[i])), 1) << ' ';
            s << "\"/>\n";
            for (std::size_t i : idx) {
                const double px = x(rows[i].medianMs), py = y(err(rows[i]));
                s << "<circle cx=\"" << fixed(px, 1) << "\" cy=\"" << fixed(py, 1) << "\" r=\"4\" fill=\""
                  << shaderColour(shader) << "\"><title>" << rowName(rows[i]) << ": " << fixed(rows[i].medianMs, 2)
                  << " ms, " << fixed(err(rows[i]), 2) << "</title></circle>"
                  << "<text x=\"" << fixed(px + 5, 1) << "\" y=\"" << fixed(py - 5, 1) << "\" font-size=\"10\" fill=\""
                  << shaderColour(shader) << "\">" << rows[i].level << "</text>\n";
            }
        }
        if (panel == 0 && !front.empty()) {
            // Staircase: from each front point right to the next one's time, then down.
            s << "<path fill=\"none\" stroke=\"black\" stroke-dasharray=\"5,3\" d=\"M";
            for (std::size_t k = 0; k < front.size(); ++k) {
                const Row& r = rows[front[k]];
                if (k > 0) s << " H" << fixed(x(r.medianMs), 1) << " V";
                s << (k == 0 ? fixed(x(r.medianMs), 1) + " " : std::string()) << fixed(y(fullError(r)), 1);
            }
            s << "\"/>\n";
            for (std::size_t i : front)
                s << "<circle cx=\"" << fixed(x(rows[i].medianMs), 1) << "\" cy=\"" << fixed(y(fullError(rows[i])), 1)
                  << "\" r=\"7\" fill=\"none\" stroke=\"black\"/>\n";
        }
        s << "</g>\n";
    }
    s << "</svg>\n";

    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write " + path.string());
    f << s.str();
    if (!f) throw std::runtime_error("error writing " + path.string());
}

}  // namespace prism::bench
