// prism_bench_rain --trade: what a cheaper rain setting costs in accuracy. Every setting
// (particles per drop, level-of-detail rings and falloff, streak technique) draws the rain
// scene's view 0 for a number of frames; the rain layer (the light the streaks add, on
// black, in a float framebuffer) is averaged over the frames, scaled to the default
// particle density (0.05 per drop), and compared per pixel with a dense reference without LOD averaged
// over more frames. Also the streak density per distance band, from the particles. Prints
// cost and error side by side, the Pareto front (prism/reference/pareto.hpp), the
// recommended default and what LOD costs; writes the CSV and the plot (trade_plot.hpp).
//
//     LP_NUM_THREADS=2 prism_bench_rain --trade --out bench/rain/results [--trade-size 320] [--trade-frames 16]
#pragma once

#include <string>

namespace prism::rain::bench {

struct RainTradeOptions {
    std::string out = ".";      // rain_trade.csv and rain_trade.svg
    int size = 320;             // framebuffer edge in pixels
    int frames = 16;            // averaged frames per setting, 0.1 s of rain apart
    int referenceFrames = 40;   // averaged frames of the reference
    double referencePpd = 0.2;  // particles per drop of the reference (4x the default)
    double budgetMs = 0.0;      // > 0: also print the best light error among settings at most this many ms
};

// Runs every setting and the reference (needs a current GL 4.3 context); returns 0.
int runRainTrade(const RainTradeOptions& options);

}  // namespace prism::rain::bench
