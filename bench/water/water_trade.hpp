// prism_bench_water --trade: what a cheaper water setting costs in accuracy. Every setting
// (grid 64^2 .. 512^2, substep at the stability bound or half of it, smoothing kernel,
// CPU and compute-shader step) simulates the same terrain and rain as a fine reference
// (512^2, a quarter of the stable substep); each result is resampled onto a common 64^2
// grid (prism/water/depth_comparison.hpp) and compared. Prints cost and error side by
// side, the Pareto front (prism/reference/pareto.hpp) and a recommended setting per use;
// writes the CSV and the plot (trade_plot.hpp).
//
//     prism_bench_water --trade [--trade-seconds 60] [--trade-csv F.csv] [--trade-svg F.svg] [--no-gpu]
#pragma once

#include <string>

#include "prism/water/height_field.hpp"

namespace prism::water::bench {

struct WaterTradeOptions {
    double seconds = 60.0;          // simulated time of every run: rain for the first half, then none
    double rainMmPerHour = 1016.0;  // 10 x cloudburst: 8.5 mm in 30 s, so that puddles form
    int commonGrid = 64;            // the grid every result is compared on
    bool gpu = true;                // also the compute-shader step (needs a current GL 4.3 context)
    std::string csv, svg;
};

// Runs every setting and the reference, prints the tables; returns 0.
int runWaterTrade(const WaterTradeOptions& options);

// The benches' terrain: a 64 m square of procedural terrain at grid x grid cells.
HeightField benchTerrain(int grid);
// Process CPU time (all threads) in milliseconds.
double processCpuMs();

}  // namespace prism::water::bench
