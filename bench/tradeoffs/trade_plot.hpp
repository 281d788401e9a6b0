// The plot of a speed/accuracy trade, one mechanism for the benches that publish one
// (prism_bench_water --trade, prism_bench_rain --trade): cost against error on log-log
// axes, one colour per series, the Pareto front (prism/reference/pareto.hpp) filled and
// joined, every other setting hollow.
//
//     std::vector<prism::bench::TradePoint> points = {{"cpu", "128^2", 12.0, 0.8, true}, ...};
//     prism::bench::writeTradeSvg("results/trade.svg", points,
//                                 {"Water: cost vs error", "llvmpipe", "ms per simulated s", "mean |depth| mm"});
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace prism::bench {

struct TradePoint {
    std::string series, label;  // colour group, and the setting (a tooltip)
    double cost = 0.0, error = 0.0;
    bool front = false;
};

struct TradeAxes {
    std::string title, subtitle, cost, error;
};

// Values <= 0 are drawn at the axis' lower end.
void writeTradeSvg(const std::filesystem::path& path, const std::vector<TradePoint>& points, const TradeAxes& axes);

}  // namespace prism::bench
