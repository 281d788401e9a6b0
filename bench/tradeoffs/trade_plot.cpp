// The SVG plot of a speed/accuracy trade (trade_plot.hpp).
#include "trade_plot.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace prism::bench {
namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2"};

// Decades [lo, hi] that hold every positive value.
void decades(const std::vector<double>& v, double& lo, double& hi) {
    double a = INFINITY, b = 0.0;
    for (double x : v)
        if (x > 0.0) a = std::min(a, x), b = std::max(b, x);
    if (!(b > 0.0)) a = b = 1.0;
    lo = std::pow(10.0, std::floor(std::log10(a)));
    hi = std::pow(10.0, std::ceil(std::log10(b)));
    if (hi <= lo) hi = lo * 10.0;
}

struct Frame {
    double left = 80, right = 170, top = 56, bottom = 52, W = 720, H = 460;
    double xLo = 1, xHi = 10, yLo = 1, yHi = 10;
    double x(double v) const {
        const double t = (std::log10(std::max(v, xLo)) - std::log10(xLo)) / (std::log10(xHi) - std::log10(xLo));
        return left + t * (W - left - right);
    }
    double y(double v) const {
        const double t = (std::log10(std::max(v, yLo)) - std::log10(yLo)) / (std::log10(yHi) - std::log10(yLo));
        return H - bottom - t * (H - top - bottom);
    }
};

void grid(std::ostream& s, const Frame& f, const TradeAxes& axes) {
    for (double d = f.xLo; d <= f.xHi * 1.0001; d *= 10)
        s << "<line x1='" << f.x(d) << "' x2='" << f.x(d) << "' y1='" << f.top << "' y2='" << f.H - f.bottom
          << "' stroke='#ddd'/><text x='" << f.x(d) << "' y='" << f.H - f.bottom + 16 << "' text-anchor='middle'>" << d
          << "</text>\n";
    for (double d = f.yLo; d <= f.yHi * 1.0001; d *= 10)
        s << "<line x1='" << f.left << "' x2='" << f.W - f.right << "' y1='" << f.y(d) << "' y2='" << f.y(d)
          << "' stroke='#ddd'/><text x='" << f.left - 6 << "' y='" << f.y(d) + 4 << "' text-anchor='end'>" << d
          << "</text>\n";
    s << "<text x='" << (f.left + f.W - f.right) / 2 << "' y='" << f.H - 14 << "' text-anchor='middle'>" << axes.cost
      << " (log)</text>\n<text transform='translate(16," << (f.top + f.H - f.bottom) / 2
      << ") rotate(-90)' text-anchor='middle'>" << axes.error << " (log)</text>\n";
}

}  // namespace

void writeTradeSvg(const std::filesystem::path& path, const std::vector<TradePoint>& points, const TradeAxes& axes) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    Frame f;
    std::vector<double> xs, ys;
    for (const TradePoint& p : points) xs.push_back(p.cost), ys.push_back(p.error);
    decades(xs, f.xLo, f.xHi);
    decades(ys, f.yLo, f.yHi);
    std::ofstream s(path);
    s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << f.W << "' height='" << f.H
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n<text x='"
      << f.left << "' y='22' font-size='15'>" << axes.title << "</text>\n<text x='" << f.left << "' y='40' fill='#555'>"
      << axes.subtitle << "</text>\n";
    grid(s, f, axes);
    std::vector<const TradePoint*> front;
    for (const TradePoint& p : points)
        if (p.front) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](const TradePoint* a, const TradePoint* b) { return a->cost < b->cost; });
    s << "<polyline fill='none' stroke='#444' stroke-dasharray='4 3' points='";
    for (const TradePoint* p : front) s << f.x(p->cost) << "," << f.y(p->error) << " ";
    s << "'/>\n";
    std::map<std::string, const char*> colour;
    for (const TradePoint& p : points) {
        if (!colour.count(p.series)) {
            const char* c = kColours[colour.size() % std::size(kColours)];
            const double ly = f.top + 8 + 18 * static_cast<double>(colour.size());
            colour[p.series] = c;
            s << "<circle cx='" << f.W - f.right + 18 << "' cy='" << ly << "' r='4' fill='" << c << "'/><text x='"
              << f.W - f.right + 28 << "' y='" << ly + 4 << "'>" << p.series << "</text>\n";
        }
        const char* c = colour[p.series];
        s << "<circle cx='" << f.x(p.cost) << "' cy='" << f.y(p.error) << "' r='" << (p.front ? 5 : 3.5) << "' fill='"
          << (p.front ? c : "none") << "' stroke='" << c << "'><title>" << p.series << " " << p.label << ": " << p.cost
          << ", " << p.error << "</title></circle>\n";
    }
    s << "<text x='" << f.W - f.right + 12 << "' y='" << f.top + 26 + 18 * static_cast<double>(colour.size())
      << "' fill='#444'>filled, dashed: Pareto front</text>\n</svg>\n";
}

}  // namespace prism::bench
