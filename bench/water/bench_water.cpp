// prism_bench_water: how long one water substep takes on the CPU (one thread and all
// cores) and as compute shaders, for grids of 128^2 to 1024^2 cells, and how long the
// water scene takes to draw. Median of repeated runs; GPU times end with glFinish.
// Beside the 512^2 CPU figure it prints the memory floor: the bytes a substep's passes
// read and write (CpuWaterSimulation::bytesPerCellPerSubstep) divided by this machine's
// copy bandwidth, measured in the same run (a STREAM-like copy of two 64 MiB arrays, best
// of 7), and the step's ratio to it against the target (at least 60 % of the floor). The
// CPU-time column is the process CPU time per substep, which a machine busy with other
// work inflates less than the wall time.
//
//   prism_bench_water [--grids 128,256,512,1024] [--width 800 --height 600] [--no-gpu]
//                     [--no-render] [--csv docs/water-bench.csv] [--svg docs/water-bench.svg]
//   prism_bench_water --trade ...   the speed/accuracy trade instead (water_trade.hpp)
//
// Each case: a procedural terrain with procedural permeability, wet from 30 s of
// cloudburst rain, then timed steps of the largest stable dt (one substep each).
#include <CLI/CLI.hpp>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_scene.hpp"
#include "water_trade.hpp"

namespace {

using namespace prism::water;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

struct Row {
    int grid = 0;
    double cpuStepMs = 0.0, gpuStepMs = 0.0, renderMs = 0.0;
    double cpuOneThreadMs = 0.0, cpuTimeMs = 0.0;  // one thread (wall); process CPU time per substep
    int threads = 1;
    int cpuRuns = 0, gpuRuns = 0, renderRuns = 0;
    double cellsPerSecondCpu() const { return grid * static_cast<double>(grid) / (cpuStepMs * 1e-3); }
};

int runsFor(int grid) {
    return grid <= 128 ? 21 : grid <= 256 ? 11 : grid <= 512 ? 7 : 5;
}

template <class Sim>
double timeSteps(Sim& sim, int runs, bool gpu, double* cpuMs = nullptr) {
    const double dt = maxStableDt(sim.params(), sim.terrain().cellSize);
    std::vector<double> ms, cpu;
    for (int r = 0; r < runs; ++r) {
        const double cpu0 = bench::processCpuMs();
        const auto start = Clock::now();
        sim.advance(dt);
        if (gpu) glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        cpu.push_back(bench::processCpuMs() - cpu0);
    }
    if (cpuMs) *cpuMs = median(cpu);
    return median(ms);
}

// STREAM-like copy bandwidth: bytes read + written per second copying 64 MiB, best of 7.
double copyBandwidthBytesPerSecond() {
    const std::size_t n = (64u << 20) / sizeof(float);
    std::vector<float> a(n, 1.0f), b(n, 0.0f);
    double best = 0.0;
    for (int r = 0; r < 7; ++r) {
        const auto start = Clock::now();
        std::memcpy(b.data(), a.data(), n * sizeof(float));
        const double s = std::chrono::duration<double>(Clock::now() - start).count();
        best = std::max(best, 2.0 * static_cast<double>(n * sizeof(float)) / s);
        a[r] = b[n - 1 - static_cast<std::size_t>(r)];  // keep the copies observable
    }
    return best;
}

constexpr double kTargetShareOfFloor = 0.60;  // the 512^2 step at >= 60 % of the memory floor

void wet(WaterSimulation& sim) {
    sim.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst)) * 20.0);
    const double dt = maxStableDt(sim.params(), sim.terrain().cellSize);
    for (int i = 0; i < 8; ++i) sim.advance(dt);
    sim.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Cloudburst)));
}

std::string fmt(double v, int precision = 2) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows, const std::string& device, int w,
              int h) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream f(path);
    f << "# prism_bench_water on " << device << "; render " << w << "x" << h << "\n";
    f << "grid,cells,cpu_step_ms,cpu_threads,cpu_one_thread_ms,cpu_time_ms,gpu_step_ms,render_ms,cpu_runs,gpu_runs,"
         "render_runs\n";
    for (const Row& r : rows)
        f << r.grid << "," << r.grid * r.grid << "," << fmt(r.cpuStepMs, 3) << "," << r.threads << ","
          << fmt(r.cpuOneThreadMs, 3) << "," << fmt(r.cpuTimeMs, 3) << "," << fmt(r.gpuStepMs, 3) << ","
          << fmt(r.renderMs, 3) << "," << r.cpuRuns << "," << r.gpuRuns << "," << r.renderRuns << "\n";
}

// Log-log plot of the three times against the cell count.
void writeSvg(const std::filesystem::path& path, const std::vector<Row>& rows, const std::string& subtitle) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    const double W = 640, H = 420, left = 70, right = 150, top = 50, bottom = 50;
    double lo = 1e30, hi = 0;
    for (const Row& r : rows)
        for (double v : {r.cpuStepMs, r.gpuStepMs, r.renderMs})
            if (v > 0) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
    const double yMin = std::pow(10.0, std::floor(std::log10(lo))), yMax = std::pow(10.0, std::ceil(std::log10(hi)));
    const double xMin = std::log2(rows.front().grid * 1.0 * rows.front().grid) - 0.5;
    const double xMax = std::log2(rows.back().grid * 1.0 * rows.back().grid) + 0.5;
    auto X = [&](double cells) { return left + (std::log2(cells) - xMin) / (xMax - xMin) * (W - left - right); };
    auto Y = [&](double ms) {
        return top + (std::log10(yMax) - std::log10(ms)) / (std::log10(yMax) - std::log10(yMin)) * (H - top - bottom);
    };
    std::ofstream s(path);
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << left << "\" y=\"22\" font-size=\"15\">Water step and scene render time vs grid size</text>\n";
    s << "<text x=\"" << left << "\" y=\"38\" fill=\"#555\">" << subtitle << "</text>\n";
    for (double d = yMin; d <= yMax * 1.0001; d *= 10) {
        s << "<line x1=\"" << left << "\" x2=\"" << W - right << "\" y1=\"" << Y(d) << "\" y2=\"" << Y(d)
          << "\" stroke=\"#ddd\"/>\n<text x=\"" << left - 8 << "\" y=\"" << Y(d) + 4 << "\" text-anchor=\"end\">" << d
          << " ms</text>\n";
    }
    for (const Row& r : rows) {
        const double c = r.grid * 1.0 * r.grid;
        s << "<line x1=\"" << X(c) << "\" x2=\"" << X(c) << "\" y1=\"" << top << "\" y2=\"" << H - bottom
          << "\" stroke=\"#eee\"/>\n<text x=\"" << X(c) << "\" y=\"" << H - bottom + 18 << "\" text-anchor=\"middle\">"
          << r.grid << "&#178;</text>\n";
    }
    s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 10
      << "\" text-anchor=\"middle\">grid (cells, log scale)</text>\n";
    struct Series {
        const char* name;
        const char* colour;
        double Row::*field;
    };
    const Series series[] = {{"CPU step", "#1f77b4", &Row::cpuStepMs},
                             {"GPU step (compute)", "#d62728", &Row::gpuStepMs},
                             {"scene render", "#2ca02c", &Row::renderMs}};
    int legend = 0;
    for (const Series& ser : series) {
        s << "<polyline fill=\"none\" stroke=\"" << ser.colour << "\" stroke-width=\"2\" points=\"";
        for (const Row& r : rows)
            if (r.*ser.field > 0) s << X(r.grid * 1.0 * r.grid) << "," << Y(r.*ser.field) << " ";
        s << "\"/>\n";
        for (const Row& r : rows)
            if (r.*ser.field > 0)
                s << "<circle cx=\"" << X(r.grid * 1.0 * r.grid) << "\" cy=\"" << Y(r.*ser.field)
                  << "\" r=\"3.5\" fill=\"" << ser.colour << "\"/>\n";
        const double ly = top + 10 + 20 * legend++;
        s << "<line x1=\"" << W - right + 12 << "\" x2=\"" << W - right + 32 << "\" y1=\"" << ly << "\" y2=\"" << ly
          << "\" stroke=\"" << ser.colour << "\" stroke-width=\"2\"/>\n<text x=\"" << W - right + 36 << "\" y=\""
          << ly + 4 << "\">" << ser.name << "</text>\n";
    }
    s << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Water step (CPU and compute shaders) and water-scene render times"};
    std::vector<int> grids = {128, 256, 512, 1024};
    int width = 800, height = 600;
    std::string csv, svg;
    bool noGpu = false, noRender = false;
    app.add_option("--grids", grids, "grid edge lengths")->delimiter(',');
    app.add_option("--width", width, "render width");
    app.add_option("--height", height, "render height");
    app.add_option("--csv", csv, "write the table as CSV");
    app.add_option("--svg", svg, "write the plot as SVG");
    app.add_flag("--no-gpu", noGpu, "skip the compute-shader step");
    app.add_flag("--no-render", noRender, "skip the scene render");
    bench::WaterTradeOptions trade;
    bool tradeMode = false;
    app.add_flag("--trade", tradeMode, "measure the speed/accuracy trade against a fine reference instead");
    app.add_option("--trade-seconds", trade.seconds, "simulated seconds per trade run")->check(CLI::Range(1.0, 3600.0));
    app.add_option("--trade-csv", trade.csv, "write the trade table as CSV");
    app.add_option("--trade-svg", trade.svg, "write the trade plot as SVG");
    CLI11_PARSE(app, argc, argv);
    std::sort(grids.begin(), grids.end());
    try {
        auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
        const std::string device = context->info().renderer;
        std::cout << "prism_bench_water on " << device << " (" << context->info().version << ")\n";
        if (tradeMode) {
            trade.gpu = !noGpu;
            return bench::runWaterTrade(trade);
        }
        std::vector<Row> rows;
        for (int grid : grids) {
            Row row;
            row.grid = grid;
            const HeightField terrain = bench::benchTerrain(grid);
            const std::vector<float> k = proceduralPermeability(terrain);
            const int runs = runsFor(grid);
            {
                CpuWaterSimulation one(terrain, k, {.threads = 1});
                wet(one);
                row.cpuOneThreadMs = timeSteps(one, runs, false);
                CpuWaterSimulation cpu(terrain, k, {});
                wet(cpu);
                row.cpuStepMs = timeSteps(cpu, runs, false, &row.cpuTimeMs);
                row.threads = cpu.threads();
                row.cpuRuns = runs;
            }
            if (!noGpu) {
                GpuWaterSimulation gpu(terrain, k, {});
                wet(gpu);
                glFinish();
                row.gpuStepMs = timeSteps(gpu, runs, true);
                row.gpuRuns = runs;
            }
            if (!noRender) {
                WaterSceneDescription d;
                d.terrain = terrain;
                d.permeability = k;
                d.rainMmPerHour = rainRateMmPerHour(RainClass::Cloudburst);
                d.fog = prism::view::Fog{.color = {0.66f, 0.68f, 0.70f}, .density = 0.01f};
                WaterScene scene(std::move(d));
                wet(scene.water()->simulation());
                WaterSceneRenderer renderer(scene);
                prism::gl::Framebuffer fb(width, height);
                fb.bind();
                const prism::view::Camera cam = groundCamera(scene.terrain());
                renderer.draw(cam, width, height);  // builds the programs
                glFinish();
                std::vector<double> ms;
                for (int r = 0; r < runs; ++r) {
                    const auto start = Clock::now();
                    renderer.draw(cam, width, height);
                    glFinish();
                    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
                }
                row.renderMs = median(ms);
                row.renderRuns = runs;
            }
            rows.push_back(row);
            std::cout << "  " << grid << "^2 done\n" << std::flush;
        }
        const double bandwidth = copyBandwidthBytesPerSecond();
        const int bytesPerCell = CpuWaterSimulation::bytesPerCellPerSubstep(WaterParams{}.smoothingKernel > 1);
        std::cout << "\n| grid | cells | CPU 1 thread (ms) | CPU " << rows.front().threads
                  << " threads (ms) | CPU time (ms) | memory floor (ms) | GPU step (ms) | GPU / CPU | CPU Mcells/s | "
                     "render "
                  << width << "x" << height << " (ms) |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const Row& r : rows) {
            const double floorMs = static_cast<double>(r.grid) * r.grid * bytesPerCell / bandwidth * 1e3;
            std::cout << "| " << r.grid << "^2 | " << r.grid * r.grid << " | " << fmt(r.cpuOneThreadMs) << " | "
                      << fmt(r.cpuStepMs) << " | " << fmt(r.cpuTimeMs) << " | " << fmt(floorMs) << " | "
                      << (r.gpuStepMs > 0 ? fmt(r.gpuStepMs) : "-") << " | "
                      << (r.gpuStepMs > 0 ? fmt(r.gpuStepMs / r.cpuStepMs) : "-") << " | "
                      << fmt(r.cellsPerSecondCpu() * 1e-6) << " | " << fmt(r.renderMs) << " |\n";
        }
        std::cout << "(median of " << rows.front().cpuRuns << " (" << rows.front().grid << "^2) to "
                  << rows.back().cpuRuns << " (" << rows.back().grid
                  << "^2) runs; one step = one substep of the largest stable dt; GPU times end with glFinish)\n";
        std::cout << "memory: a substep reads and writes " << bytesPerCell << " bytes per cell; copy bandwidth "
                  << fmt(bandwidth * 1e-9) << " GB/s (STREAM-like copy, 64 MiB, best of 7); memory floor = cells x "
                  << bytesPerCell << " B / bandwidth\n";
        for (const Row& r : rows)
            if (r.grid == 512) {
                const double floorMs = 512.0 * 512.0 * bytesPerCell / bandwidth * 1e3;
                const double share = floorMs / r.cpuStepMs;
                std::cout << "512^2: " << fmt(r.cpuStepMs) << " ms per substep on " << r.threads
                          << " threads; memory floor " << fmt(floorMs)
                          << " ms; floor / step = " << fmt(share * 100.0, 0)
                          << " % (target >= " << fmt(kTargetShareOfFloor * 100.0, 0)
                          << " %: " << (share >= kTargetShareOfFloor ? "met" : "NOT met")
                          << "); the fused step streams " << CpuWaterSimulation::bytesStreamedPerCellPerSubstep()
                          << " of those " << bytesPerCell << " B per cell; " << std::thread::hardware_concurrency()
                          << " hardware threads; load average when run: see `uptime`\n";
            }
        if (!csv.empty()) writeCsv(csv, rows, device, width, height);
        if (!svg.empty())
            writeSvg(svg, rows, device + ", render " + std::to_string(width) + "x" + std::to_string(height));
        if (!csv.empty() || !svg.empty()) std::cout << "wrote " << csv << " " << svg << "\n";
    } catch (const std::exception& e) {
        std::cerr << "prism_bench_water: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
