// The water trade of prism_bench_water --trade (see water_trade.hpp).
#include "water_trade.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include "prism/gl/gl.hpp"
#include "prism/reference/pareto.hpp"
#include "prism/water/depth_comparison.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"
#include "trade_plot.hpp"

namespace prism::water::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Setting {
    bool gpu = false;
    int grid = 0;
    float courant = 0.7f;
    int kernel = 5;
};

struct Outcome {
    Setting s;
    double msPerSecond = 0.0, cpuMsPerSecond = 0.0, substepSeconds = 0.0;
    long substeps = 0;
    bool probed = false;  // GPU at 512^2: cost from a short run, water from the CPU run
    std::vector<float> depth;
    MassLedger ledger;
    DepthComparison error;
    double storedError = 0.0, lostError = 0.0;  // |m^3 - the reference's| / the reference's rain in (m^3)
    bool front = false;
};

// The compute-shader step on llvmpipe costs ~200 ms per 512^2 substep; the whole run would
// take minutes, so its cost comes from this many simulated seconds.
constexpr double kGpuProbeSeconds = 5.0;
constexpr int kGpuFullRunMaxGrid = 256;

std::string fmt(double v, int precision) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

std::string name(const Setting& s) {
    return std::string(s.gpu ? "gpu" : "cpu") + " " + std::to_string(s.grid) + "^2 C" + fmt(s.courant, 3) + " k" +
           std::to_string(s.kernel);
}

std::unique_ptr<WaterSimulation> makeSimulation(const Setting& s) {
    const HeightField terrain = benchTerrain(s.grid);
    std::vector<float> k = proceduralPermeability(terrain);
    WaterParams p;
    p.courantNumber = s.courant;
    p.smoothingKernel = s.kernel;
    if (s.gpu) return std::make_unique<GpuWaterSimulation>(terrain, std::move(k), p);
    return std::make_unique<CpuWaterSimulation>(terrain, std::move(k), p);
}

Outcome simulate(const Setting& s, const WaterTradeOptions& o, double seconds) {
    Outcome out;
    out.s = s;
    auto sim = makeSimulation(s);
    const double cpu0 = processCpuMs();
    const auto start = Clock::now();
    // One advance() per half, so every substep is as long as the setting allows.
    sim->setRainRate(mmPerHourToMetresPerSecond(o.rainMmPerHour));
    out.substepSeconds = sim->advance(seconds * 0.5).dt;
    sim->setRainRate(0.0);
    sim->advance(seconds * 0.5);
    if (s.gpu) glFinish();
    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    out.msPerSecond = wall / seconds;
    out.cpuMsPerSecond = (processCpuMs() - cpu0) / seconds;
    out.substeps = sim->substepsDone();
    out.depth = sim->depth();
    out.ledger = sim->ledger();
    return out;
}

std::vector<Setting> settings(bool gpu) {
    std::vector<Setting> list;
    for (int grid : {64, 128, 256, 512})
        for (float courant : {0.7f, 0.35f})
            for (int kernel : {1, 3, 5}) list.push_back({false, grid, courant, kernel});
    if (gpu)
        for (int grid : {64, 128, 256, 512}) list.push_back({true, grid, 0.7f, 5});
    return list;
}

// The GPU result at 512^2 is the CPU's (bit-identical on llvmpipe: checked here on the
// smaller grids and by water.GpuCpuAgreement), its cost from a short run.
Outcome runSetting(const Setting& s, const WaterTradeOptions& o, const std::vector<Outcome>& done) {
    if (!s.gpu || s.grid <= kGpuFullRunMaxGrid) {
        Outcome r = simulate(s, o, o.seconds);
        for (const Outcome& c : done)
            if (s.gpu && !c.s.gpu && c.s.grid == s.grid && c.s.courant == s.courant && c.s.kernel == s.kernel)
                std::cout << "  " << name(s) << ": depths "
                          << (std::memcmp(c.depth.data(), r.depth.data(), r.depth.size() * 4) == 0 ? "bit-identical"
                                                                                                   : "DIFFERENT")
                          << " to the CPU step's\n";
        return r;
    }
    Outcome probe = simulate(s, o, kGpuProbeSeconds);
    for (const Outcome& c : done)
        if (!c.s.gpu && c.s.grid == s.grid && c.s.courant == s.courant && c.s.kernel == s.kernel) {
            Outcome r = c;
            r.s = s;
            r.probed = true;
            r.msPerSecond = probe.msPerSecond;
            r.cpuMsPerSecond = probe.cpuMsPerSecond;
            return r;
        }
    return probe;
}

void compare(Outcome& r, const Outcome& reference, int common) {
    const std::vector<float> mine = resampleDepth(r.depth, r.s.grid, r.s.grid, common, common);
    const std::vector<float> ref = resampleDepth(reference.depth, reference.s.grid, reference.s.grid, common, common);
    r.error = compareDepth(mine, ref);
    const auto m3 = [](const MassLedger& l, double v) { return v * l.cellArea; };
    const double rainIn = m3(reference.ledger, reference.ledger.rainIn);
    r.storedError = std::abs(m3(r.ledger, r.ledger.stored) - m3(reference.ledger, reference.ledger.stored)) / rainIn;
    r.lostError =
        std::abs(m3(r.ledger, r.ledger.lostThroughBorder) - m3(reference.ledger, reference.ledger.lostThroughBorder)) /
        rainIn;
}

void printTable(const std::vector<Outcome>& rows) {
    std::cout << "\n| setting | grid | substep (s) | kernel | substeps | ms per simulated s | CPU ms per simulated s | "
                 "depth mean err (mm) | depth p95 err (mm) | wetted area err (%) | stored err (% of rain) | lost err "
                 "(% of rain) | "
                 "ledger closure | front |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (const Outcome& r : rows)
        std::cout << "| " << name(r.s) << " | " << r.s.grid << "^2 | " << fmt(r.substepSeconds, 4) << " | "
                  << r.s.kernel << " | " << r.substeps
                  << (r.probed ? " (cost from " + fmt(kGpuProbeSeconds, 0) + " s)" : "") << " | "
                  << fmt(r.msPerSecond, 1) << " | " << fmt(r.cpuMsPerSecond, 1) << " | " << fmt(r.error.meanAbsMm, 3)
                  << " | " << fmt(r.error.p95AbsMm, 3) << " | " << fmt(r.error.wettedAreaError() * 100.0, 2) << " | "
                  << fmt(r.storedError * 100.0, 2) << " | " << fmt(r.lostError * 100.0, 2) << " | " << std::scientific
                  << std::setprecision(1) << r.ledger.relativeError() << std::defaultfloat << " | "
                  << (r.front ? "**yes**" : "") << " |\n";
}

// A scene's puddles are simulated once, at load: the cheapest setting whose mean depth error
// is under 1 mm (the depth the trade counts as wet) with the wetted area within 5 %. The
// viewer's live simulation must keep up with real time on top of drawing: the most
// accurate setting within a quarter of one core (250 ms of CPU time per simulated second).
void recommend(const std::vector<Outcome>& rows, const std::vector<std::size_t>& front) {
    std::vector<double> cost, error;
    std::vector<std::size_t> areaOk;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        cost.push_back(rows[i].cpuMsPerSecond);
        error.push_back(rows[i].error.meanAbsMm);
        if (rows[i].error.wettedAreaError() <= 0.05) areaOk.push_back(i);
    }
    const auto puddles = areaOk.empty() ? std::nullopt : reference::cheapestWithin(cost, error, 1.0, areaOk);
    std::cout << "\nrecommended for a scene's puddles (mean depth error <= 1 mm, wetted area within 5 %): "
              << (puddles ? name(rows[*puddles].s) : "none") << "\n";
    std::optional<std::size_t> live;
    for (std::size_t i : front)
        if (rows[i].cpuMsPerSecond <= 250.0) live = i;
    std::cout << "recommended for the viewer's live simulation (most accurate within 250 ms of CPU time per "
                 "simulated s): "
              << (live ? name(rows[*live].s) : "none") << "\n";
}

void writeCsv(const std::string& path, const std::vector<Outcome>& rows) {
    std::ofstream f(path);
    f << "setting,backend,grid,courant,substep_s,kernel,substeps,ms_per_sim_s,cpu_ms_per_sim_s,depth_mean_err_mm,"
         "depth_p95_err_mm,wetted_area_err,stored_err,lost_err,ledger_closure,pareto\n";
    for (const Outcome& r : rows)
        f << name(r.s) << "," << (r.s.gpu ? "gpu" : "cpu") << "," << r.s.grid << "," << r.s.courant << ","
          << r.substepSeconds << "," << r.s.kernel << "," << r.substeps << "," << r.msPerSecond << ","
          << r.cpuMsPerSecond << "," << r.error.meanAbsMm << "," << r.error.p95AbsMm << "," << r.error.wettedAreaError()
          << "," << r.storedError << "," << r.lostError << "," << r.ledger.relativeError() << "," << (r.front ? 1 : 0)
          << "\n";
}

void writeSvg(const std::string& path, const std::vector<Outcome>& rows, const WaterTradeOptions& o) {
    std::vector<prism::bench::TradePoint> points;
    for (const Outcome& r : rows)
        points.push_back({std::string(r.s.gpu ? "GPU" : "CPU") + ", kernel " + std::to_string(r.s.kernel), name(r.s),
                          r.cpuMsPerSecond, r.error.meanAbsMm, r.front});
    prism::bench::writeTradeSvg(path, points,
                                {"Water: cost against depth error (reference 512^2, quarter substep)",
                                 fmt(o.seconds / 2, 0) + " s of " + fmt(o.rainMmPerHour, 0) + " mm/h, then " +
                                     fmt(o.seconds / 2, 0) + " s dry, on a 64 m terrain; errors on a common 64^2 grid",
                                 "CPU ms per simulated second (all threads)", "mean |depth - reference| (mm)"});
}

}  // namespace

HeightField benchTerrain(int grid) {
    // A 64 m square whatever the resolution: finer grids have smaller cells.
    return proceduralTerrain(
        {.width = grid, .height = grid, .cellSize = 64.0f / static_cast<float>(grid), .relief = 3.0f, .seed = 1});
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

int runWaterTrade(const WaterTradeOptions& o) {
    const Setting referenceSetting{false, 512, 0.175f, 5};
    std::cout << "reference: " << name(referenceSetting) << "; every run: " << o.seconds / 2 << " s of "
              << o.rainMmPerHour << " mm/h, then " << o.seconds / 2 << " s without rain\n"
              << std::flush;
    const Outcome reference = simulate(referenceSetting, o, o.seconds);
    const std::vector<float> refCommon =
        resampleDepth(reference.depth, reference.s.grid, reference.s.grid, o.commonGrid, o.commonGrid);
    double refMean = 0.0;
    for (float d : refCommon) refMean += d * 1e3 / static_cast<double>(refCommon.size());
    std::vector<Outcome> rows;
    for (const Setting& s : settings(o.gpu)) {
        rows.push_back(runSetting(s, o, rows));
        compare(rows.back(), reference, o.commonGrid);
        std::cout << "  " << name(s) << " done\n" << std::flush;
    }
    std::vector<double> cost, error;
    // Cost is the process CPU time (all threads): the machine's two cores are shared, and
    // CPU time is what other load inflates least; wall time is printed beside it.
    for (const Outcome& r : rows) cost.push_back(r.cpuMsPerSecond), error.push_back(r.error.meanAbsMm);
    const std::vector<std::size_t> front = reference::paretoFront(cost, error);
    for (std::size_t i : front) rows[i].front = true;
    std::cout << "reference: " << reference.substeps << " substeps of " << fmt(reference.substepSeconds, 4) << " s, "
              << fmt(reference.msPerSecond, 1) << " ms per simulated s; mean depth on the common grid "
              << fmt(refMean, 3) << " mm, wetted " << fmt(compareDepth(refCommon, refCommon).wettedShare * 100, 1)
              << " % (deeper than 1 mm); ledger closure " << reference.ledger.relativeError() << "\n";
    printTable(rows);
    std::cout << "\nPareto front (CPU ms per simulated s vs depth mean error), cheapest first:";
    for (std::size_t i : front) std::cout << " " << name(rows[i].s) << ";";
    std::cout << "\n";
    recommend(rows, front);
    if (!o.csv.empty()) writeCsv(o.csv, rows);
    if (!o.svg.empty()) writeSvg(o.svg, rows, o);
    return 0;
}

}  // namespace prism::water::bench
