// prism_bench_rain: rain particles per frame, RainCL Table 5 (§4.6) redone (docs/rain.md).
//
//     LP_NUM_THREADS=2 prism_bench_rain --out bench/rain/results [--size 800] [--min-exp 14]
//                                       [--max-exp 24] [--frames 9] [--backend egl|osmesa]
//     prism_bench_rain --replot bench/rain/results/rain_bench.csv --subtitle "..." --out DIR
//                      (redraws the SVG from an earlier run's CSV, measures nothing)
//     LP_NUM_THREADS=2 prism_bench_rain --trade --out bench/rain/results
//                      (the speed/accuracy trade instead, rain_trade.hpp)
//     LP_NUM_THREADS=2 prism_bench_rain --baseline OLD/prism_bench_rain --max-exp 20 --out DIR
//                      (also runs an earlier build's bench for each count, interleaved, and prints both)
//
// For every count 2^e (e = --min-exp .. --max-exp; 2^23 and 2^24 only when memory allows) one
// RainSystem of exactly that many particles (fixedCount) in the default 25 m x 20 m
// cylinder with 3 m/s of wind, seen from the rain scene's view 0 (prism::rain::
// rainSceneView(0)) into an 800x800 RGBA8 framebuffer. One round = one compute update
// (timed: glFinish before, dispatch, glFinish after) and then one draw per technique
// (timed the same way: clear + draw + glFinish), in a rotating order. The first count
// starts with a dropped round that builds the programs; then `frames` rounds (fewer for
// large counts: 9 up to 2^16, 7 up to 2^18, 5 at 2^19, 3 up to 2^22, 1 above) and the
// median of each. "frame" is update + draw. Also: bytes of GPU memory per particle (simulation buffer + culled copy +
// draw commands, RainSystem::particleBytes, over the count), and the median of 3 CPU
// reference steps (CpuRainSimulation, one thread) up to 2^22. After the timed rounds one more draw per technique
// inside pipeline statistics queries (pipeline_statistics.hpp): vertex invocations, primitives entering
// clipping and fragment-shader invocations per frame; the share of particles the view culling kept
// (RainSystem::visibleCount), and the bytes per particle the frame moves (bytesMovedPerParticle).
// --no-cull draws every particle (RainDrawInputs::cullToView = false), as the turn-3 build did.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/rain/rain_system.hpp"
#include "pipeline_statistics.hpp"
#include "rain_trade.hpp"

namespace {

using namespace prism::rain;
using Clock = std::chrono::steady_clock;

struct Options {
    std::string out = ".";
    int size = 800;
    int minExp = 14;
    int maxExp = 24;
    int frames = 9;
    std::string backend;
    std::string replot;    // CSV of an earlier run: only redraw the SVG
    std::string subtitle;  // with --replot
    std::string baseline;  // an earlier build's prism_bench_rain, run for each count as well
    bool noCull = false;
};

constexpr StreakTechnique kTechniques[] = {StreakTechnique::GeometryShader, StreakTechnique::Instanced,
                                           StreakTechnique::PointSprites};

struct Row {
    int exponent = 0;
    std::uint32_t particles = 0;
    int frames = 0;
    double update = 0.0;
    double draw[3] = {0.0, 0.0, 0.0};
    double bytesPerParticle = 0.0;
    double cpuUpdate = -1.0;  // < 0: not measured
    prism::rain::bench::PipelineStatistics stats[3];
    double visibleShare = 1.0;     // particles the culling kept / particles
    double bytesMoved = 0.0;       // per particle and frame (update + cull + draw), see bytesMovedPerParticle
    double baselineUpdate = -1.0;  // < 0: no --baseline
    double baselineDraw[3] = {0.0, 0.0, 0.0};
};

// Bytes one frame reads and writes per particle (a model of the shaders' loads and stores, 48-byte
// particles): rain_update reads position and velocity (32) and writes the position (16; velocity.y only
// on a respawn); rain_cull reads the position (12) and copies each kept particle (48 read + 48 written);
// the vertex stage reads the kept particles (48). Without culling: update + 48 for every particle.
double bytesMovedPerParticle(bool culled, double visibleShare) {
    const double update = 32.0 + 16.0;
    return culled ? update + 12.0 + visibleShare * (48.0 + 48.0 + 48.0) : update + 48.0;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

int framesFor(int exponent, int maxFrames) {
    const int f = exponent <= 16 ? 9 : exponent <= 18 ? 7 : exponent <= 19 ? 5 : exponent <= 22 ? 3 : 1;
    return std::max(1, std::min(f, maxFrames));
}

// MemAvailable from /proc/meminfo in bytes (0 when unknown).
std::uint64_t availableMemory() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::uint64_t kb = 0;
    std::string unit;
    while (in >> key >> kb >> unit)
        if (key == "MemAvailable:") return kb * 1024;
    return 0;
}

// Timed rounds: one update, then one draw per technique in a rotating order; medians into `row`.
void timeRounds(RainSystem& rain, RainDrawInputs in, prism::gl::Framebuffer& fb, bool warmUp, Row& row) {
    std::vector<double> updates;
    std::vector<double> draws[3];
    const int first = warmUp ? 0 : 1;  // round 0 (dropped) builds the programs
    for (int round = first; round <= row.frames; ++round) {
        glFinish();
        auto t0 = Clock::now();
        rain.update(1.0f / 60.0f, in.camera.eye);
        glFinish();
        const double u = msSince(t0);
        if (round > 0) updates.push_back(u);
        for (int k = 0; k < 3; ++k) {
            const int t = (k + round) % 3;  // rotate the order between rounds
            in.technique = kTechniques[t];
            glFinish();
            t0 = Clock::now();
            fb.clear({0.33f, 0.36f, 0.42f, 1.0f});
            rain.draw(in);
            glFinish();
            const double d = msSince(t0);
            if (round > 0) draws[t].push_back(d);
        }
    }
    row.update = median(updates);
    for (int t = 0; t < 3; ++t) row.draw[t] = median(draws[t]);
}

// One untimed draw per technique inside the pipeline statistics queries; the share the culling kept.
void countWork(RainSystem& rain, RainDrawInputs in, prism::gl::Framebuffer& fb, Row& row) {
    for (int t = 0; t < 3; ++t) {
        in.technique = kTechniques[t];
        fb.clear({0.33f, 0.36f, 0.42f, 1.0f});
        row.stats[t] = prism::rain::bench::measurePipelineStatistics([&] { rain.draw(in); });
    }
    row.visibleShare = static_cast<double>(rain.visibleCount()) / std::max<std::uint32_t>(row.particles, 1);
    row.bytesMoved = bytesMovedPerParticle(in.cullToView, row.visibleShare);
}

Row measure(RainPrograms& programs, const Options& o, int exponent, bool warmUp) {
    Row row;
    row.exponent = exponent;
    row.particles = 1u << exponent;
    row.frames = framesFor(exponent, o.frames);
    RainParams params;
    params.fixedCount = row.particles;
    params.wind.strength = 3.0f;
    params.seed = 2013;
    const prism::view::Camera camera = rainSceneView(0);
    RainSystem rain(programs, params, camera.eye);
    prism::gl::Framebuffer fb(o.size, o.size);
    RainDrawInputs in;
    in.camera = camera;
    in.aspect = 1.0f;
    in.viewportHeight = o.size;
    in.cullToView = !o.noCull;
    timeRounds(rain, in, fb, warmUp, row);
    countWork(rain, in, fb, row);
    row.bytesPerParticle = static_cast<double>(rain.particleBytes()) / row.particles;  // after the draws
    if (exponent <= 22) {
        CpuRainSimulation cpu(params, camera.eye);
        std::vector<double> steps;
        for (int i = 0; i < 3; ++i) {
            const auto t0 = Clock::now();
            cpu.step(1.0f / 60.0f, camera.eye);
            steps.push_back(msSince(t0));
        }
        row.cpuUpdate = median(steps);
    }
    return row;
}

std::string fixed(double v, int digits = 1) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows) {
    std::ofstream out(path);
    out << "exponent,particles,frames,update_ms,gs_draw_ms,gs_frame_ms,instanced_draw_ms,instanced_frame_ms,"
           "points_draw_ms,points_frame_ms,bytes_per_particle,cpu_reference_update_ms,"
           "gs_fragment_invocations,instanced_fragment_invocations,points_fragment_invocations,"
           "gs_primitives,instanced_primitives,points_primitives,gs_vertex_invocations,instanced_vertex_invocations,"
           "points_vertex_invocations,visible_share,bytes_moved_per_particle,baseline_update_ms,baseline_gs_frame_ms,"
           "baseline_instanced_frame_ms,baseline_points_frame_ms\n";
    for (const auto& r : rows) {
        out << r.exponent << "," << r.particles << "," << r.frames << "," << fixed(r.update, 3);
        for (int t = 0; t < 3; ++t) out << "," << fixed(r.draw[t], 3) << "," << fixed(r.update + r.draw[t], 3);
        out << "," << fixed(r.bytesPerParticle, 1) << "," << (r.cpuUpdate < 0 ? std::string() : fixed(r.cpuUpdate, 3));
        for (int t = 0; t < 3; ++t) out << "," << r.stats[t].fragmentInvocations;
        for (int t = 0; t < 3; ++t) out << "," << r.stats[t].clippingPrimitives;
        for (int t = 0; t < 3; ++t) out << "," << r.stats[t].vertexInvocations;
        out << "," << fixed(r.visibleShare, 4) << "," << fixed(r.bytesMoved, 1);
        if (r.baselineUpdate >= 0) {
            out << "," << fixed(r.baselineUpdate, 3);
            for (int t = 0; t < 3; ++t) out << "," << fixed(r.baselineUpdate + r.baselineDraw[t], 3);
        } else {
            out << ",,,,";
        }
        out << "\n";
    }
}

std::vector<Row> readCsv(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    std::string line;
    std::getline(in, line);  // header
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
        if (f.size() < 11) throw std::runtime_error("malformed line in " + path.string() + ": " + line);
        Row r;
        r.exponent = std::stoi(f[0]);
        r.particles = static_cast<std::uint32_t>(std::stoul(f[1]));
        r.frames = std::stoi(f[2]);
        r.update = std::stod(f[3]);
        for (int t = 0; t < 3; ++t) r.draw[t] = std::stod(f[4 + 2 * t]);
        r.bytesPerParticle = std::stod(f[10]);
        r.cpuUpdate = f.size() > 11 && !f[11].empty() ? std::stod(f[11]) : -1.0;
        rows.push_back(r);
    }
    if (rows.empty()) throw std::runtime_error(path.string() + " has no rows");
    return rows;
}

// Runs an earlier build's bench for count 2^exponent alone (same size and rounds; its CSV and log go to
// the temporary folder) and keeps its medians.
void runBaseline(const Options& o, int exponent, Row& row) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("prism_bench_rain_baseline_2^" + std::to_string(exponent));
    std::filesystem::create_directories(dir);
    const std::string e = std::to_string(exponent);
    const std::string command = "'" + o.baseline + "' --min-exp " + e + " --max-exp " + e + " --frames " +
                                std::to_string(o.frames) + " --size " + std::to_string(o.size) + " --out '" +
                                dir.string() + "' > '" + (dir / "log.txt").string() + "' 2>&1";
    if (std::system(command.c_str()) != 0)
        throw std::runtime_error("the baseline bench failed: " + command + " (see " + (dir / "log.txt").string() + ")");
    const Row base = readCsv(dir / "rain_bench.csv").front();
    row.baselineUpdate = base.update;
    for (int t = 0; t < 3; ++t) row.baselineDraw[t] = base.draw[t];
}

// Log-log plot: frame time per technique (solid), compute update (dashed), 60 and 30 FPS.
void writeSvg(const std::filesystem::path& path, const std::vector<Row>& rows, const std::string& subtitle) {
    const double W = 760, H = 480, left = 70, right = 170, top = 50, bottom = 60;
    const double x0 = rows.front().exponent, x1 = std::max<double>(rows.back().exponent, x0 + 1);
    double lo = 1e9, hi = 0;
    for (const auto& r : rows) {
        lo = std::min({lo, r.update, r.draw[0], r.draw[1], r.draw[2]});
        hi = std::max({hi, r.update + r.draw[0], r.update + r.draw[1], r.update + r.draw[2]});
    }
    const double y0 = std::floor(std::log10(std::max(lo, 0.01))), y1 = std::ceil(std::log10(std::max(hi, 20.0)));
    auto X = [&](double e) { return left + (e - x0) / (x1 - x0) * (W - left - right); };
    auto Y = [&](double ms) { return top + (y1 - std::log10(std::max(ms, 1e-3))) / (y1 - y0) * (H - top - bottom); };
    std::ofstream s(path);
    s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
    s << "<text x='" << left << "' y='20' font-size='15'>Rain: ms per frame (compute update + draw), median</text>\n";
    s << "<text x='" << left << "' y='36' fill='#555'>" << subtitle << "</text>\n";
    for (double d = y0; d <= y1 + 1e-9; d += 1.0) {
        const double y = Y(std::pow(10.0, d));
        s << "<line x1='" << left << "' x2='" << W - right << "' y1='" << y << "' y2='" << y << "' stroke='#ddd'/>\n";
        s << "<text x='" << left - 8 << "' y='" << y + 4 << "' text-anchor='end'>"
          << fixed(std::pow(10.0, d), d < 0 ? 1 : 0) << "</text>\n";
    }
    for (const auto& r : rows) {
        const double x = X(r.exponent);
        s << "<line x1='" << x << "' x2='" << x << "' y1='" << top << "' y2='" << H - bottom << "' stroke='#eee'/>\n";
        s << "<text x='" << x << "' y='" << H - bottom + 16 << "' text-anchor='middle'>2^" << r.exponent << "</text>\n";
    }
    s << "<text x='" << (left + W - right) / 2 << "' y='" << H - 18 << "' text-anchor='middle'>particles</text>\n";
    s << "<text x='18' y='" << (top + H - bottom) / 2 << "' transform='rotate(-90 18 " << (top + H - bottom) / 2
      << ")' text-anchor='middle'>ms per frame (log)</text>\n";
    for (double fps : {60.0, 30.0}) {
        const double y = Y(1000.0 / fps);
        if (y < top || y > H - bottom) continue;
        s << "<line x1='" << left << "' x2='" << W - right << "' y1='" << y << "' y2='" << y
          << "' stroke='#c33' stroke-dasharray='2,4'/>\n<text x='" << W - right + 4 << "' y='" << y + 4
          << "' fill='#c33'>" << fps << " FPS</text>\n";
    }
    const char* colors[] = {"#1f77b4", "#2ca02c", "#ff7f0e"};
    const char* names[] = {"GS quads", "instanced quads", "point sprites"};
    auto polyline = [&](auto value, const char* color, const char* dash) {
        s << "<polyline fill='none' stroke='" << color << "' stroke-width='2'" << dash << " points='";
        for (const auto& r : rows) s << X(r.exponent) << "," << Y(value(r)) << " ";
        s << "'/>\n";
        for (const auto& r : rows)
            s << "<circle cx='" << X(r.exponent) << "' cy='" << Y(value(r)) << "' r='3' fill='" << color << "'/>\n";
    };
    for (int t = 0; t < 3; ++t) polyline([t](const Row& r) { return r.update + r.draw[t]; }, colors[t], "");
    polyline([](const Row& r) { return r.update; }, "#777", " stroke-dasharray='6,4'");
    double ly = top + 10;
    for (int t = 0; t < 3; ++t, ly += 20)
        s << "<line x1='" << W - right + 10 << "' x2='" << W - right + 30 << "' y1='" << ly << "' y2='" << ly
          << "' stroke='" << colors[t] << "' stroke-width='2'/><text x='" << W - right + 34 << "' y='" << ly + 4 << "'>"
          << names[t] << "</text>\n";
    s << "<line x1='" << W - right + 10 << "' x2='" << W - right + 30 << "' y1='" << ly << "' y2='" << ly
      << "' stroke='#777' stroke-width='2' stroke-dasharray='6,4'/><text x='" << W - right + 34 << "' y='" << ly + 4
      << "'>compute update only</text>\n</svg>\n";
}

// Every count from --min-exp to --max-exp; with --baseline the earlier build's bench runs for the same
// count right before (even exponents) or after (odd) this one, so load changes hit both alike.
std::vector<Row> measureCounts(const Options& o, Clock::time_point start) {
    RainPrograms programs;
    std::vector<Row> rows;
    for (int e = o.minExp; e <= o.maxExp; ++e) {
        const std::uint64_t need = (std::uint64_t{1} << e) * 48u * 3u;  // GPU copy + CPU reference + slack
        if (e >= 23 && availableMemory() < need + (1ull << 30)) {
            std::cout << "skipping 2^" << e << ": not enough free memory\n";
            continue;
        }
        Row before;
        if (!o.baseline.empty() && e % 2 == 0) runBaseline(o, e, before);
        rows.push_back(measure(programs, o, e, rows.empty()));
        Row& r = rows.back();
        if (!o.baseline.empty() && e % 2 != 0) runBaseline(o, e, before);
        r.baselineUpdate = before.baselineUpdate;
        for (int t = 0; t < 3; ++t) r.baselineDraw[t] = before.baselineDraw[t];
        std::cout << "  2^" << e << ": update " << fixed(r.update, 2) << " ms, draw gs " << fixed(r.draw[0], 2)
                  << " / instanced " << fixed(r.draw[1], 2) << " / points " << fixed(r.draw[2], 2) << " ms ("
                  << r.frames << " frames, " << fixed(msSince(start) / 1000.0, 0) << " s so far)\n"
                  << std::flush;
    }
    return rows;
}

// Cheapest technique's frame (update + draw) of a row; `baseline` picks the earlier build's.
std::pair<double, int> cheapestFrame(const Row& r, bool baseline) {
    const double update = baseline ? r.baselineUpdate : r.update;
    const double* draw = baseline ? r.baselineDraw : r.draw;
    int best = 0;
    for (int t = 1; t < 3; ++t)
        if (draw[t] < draw[best]) best = t;
    return {update + draw[best], best};
}

void printTables(const std::vector<Row>& rows) {
    std::cout << "\n| particles | update ms | GS draw | GS frame | instanced draw | instanced frame | points draw | "
                 "points frame | bytes/particle | CPU ref. update ms |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        std::cout << "| 2^" << r.exponent << " (" << r.particles << ") | " << fixed(r.update, 2);
        for (int t = 0; t < 3; ++t)
            std::cout << " | " << fixed(r.draw[t], 1) << " | " << fixed(r.update + r.draw[t], 1);
        std::cout << " | " << fixed(r.bytesPerParticle, 0) << " | "
                  << (r.cpuUpdate < 0 ? std::string("-") : fixed(r.cpuUpdate, 1)) << " |\n";
    }
    std::cout
        << "\nWork per frame (pipeline statistics of one draw; primitives = entering clipping):\n\n"
           "| particles | in view | bytes moved/particle | GS VS inv. | GS prims | GS FS inv. | instanced VS inv. "
           "| instanced FS inv. | points VS inv. | points FS inv. |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows)
        std::cout << "| 2^" << r.exponent << " | " << fixed(100.0 * r.visibleShare, 1) << " % | "
                  << fixed(r.bytesMoved, 0) << " | " << r.stats[0].vertexInvocations << " | "
                  << r.stats[0].clippingPrimitives << " | " << r.stats[0].fragmentInvocations << " | "
                  << r.stats[1].vertexInvocations << " | " << r.stats[1].fragmentInvocations << " | "
                  << r.stats[2].vertexInvocations << " | " << r.stats[2].fragmentInvocations << " |\n";
    if (rows.front().baselineUpdate < 0) return;
    const char* names[] = {"GS", "instanced", "points"};
    std::cout << "\nAgainst the baseline build (cheapest technique's frame = update + draw; target: >= 4x at 2^20):\n\n"
                 "| particles | baseline update | baseline frame | update | frame | frame ratio | target |\n"
                 "|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const auto [base, bt] = cheapestFrame(r, true);
        const auto [now, nt] = cheapestFrame(r, false);
        std::cout << "| 2^" << r.exponent << " | " << fixed(r.baselineUpdate, 1) << " | " << fixed(base, 1) << " ("
                  << names[bt] << ") | " << fixed(r.update, 1) << " | " << fixed(now, 1) << " (" << names[nt] << ") | "
                  << fixed(base / now, 2) << "x | >= 4x |\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"prism_bench_rain: rain update and draw time per particle count (RainCL Table 5)"};
    app.add_option("--out", o.out, "directory for rain_bench.csv and rain_bench.svg")->capture_default_str();
    app.add_option("--size", o.size, "framebuffer edge in pixels")->capture_default_str()->check(CLI::Range(16, 4096));
    app.add_option("--min-exp", o.minExp, "smallest count 2^e")->capture_default_str()->check(CLI::Range(0, 24));
    app.add_option("--max-exp", o.maxExp, "largest count 2^e (24 only when memory allows)")
        ->capture_default_str()
        ->check(CLI::Range(0, 24));
    app.add_option("--frames", o.frames, "most timed rounds per count (fewer for large counts)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    app.add_option("--backend", o.backend, "egl or osmesa (default: PRISM_GL_BACKEND, else egl)");
    app.add_option("--replot", o.replot, "redraw OUT/rain_bench.svg from this CSV, measure nothing");
    app.add_option("--subtitle", o.subtitle, "with --replot: the plot's subtitle (renderer, threads, size)");
    app.add_option("--baseline", o.baseline, "an earlier build's prism_bench_rain: run it for every count too");
    app.add_flag("--no-cull", o.noCull, "draw every particle (no rain_cull pass), as before the culling");
    bool trade = false;
    prism::rain::bench::RainTradeOptions tradeOptions;
    app.add_flag("--trade", trade, "measure the speed/accuracy trade against a dense reference instead");
    app.add_option("--trade-size", tradeOptions.size, "--trade: framebuffer edge")->check(CLI::Range(16, 2048));
    app.add_option("--trade-frames", tradeOptions.frames, "--trade: averaged frames per setting")
        ->check(CLI::Range(1, 1000));
    app.add_option("--trade-budget-ms", tradeOptions.budgetMs,
                   "--trade: also print the most accurate setting within this frame time (ms)")
        ->check(CLI::Range(0.0, 1e6));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (!o.replot.empty()) {
        try {
            const auto rows = readCsv(o.replot);
            const auto svg = std::filesystem::path(o.out) / "rain_bench.svg";
            writeSvg(svg, rows, o.subtitle);
            std::cout << "wrote " << svg.string() << " from " << o.replot << "\n";
            return 0;
        } catch (const std::exception& e) {
            std::cerr << "prism_bench_rain: error: " << e.what() << "\n";
            return 1;
        }
    }
    try {
        prism::gl::ContextOptions co{.majorVersion = 4, .minorVersion = 3};
        std::unique_ptr<prism::gl::Context> ctx;
        if (!o.backend.empty()) {
            auto b = prism::gl::parseBackend(o.backend);
            if (!b) throw std::invalid_argument("--backend must be egl or osmesa");
            ctx = prism::gl::createContext(*b, co);
        } else {
            ctx = prism::gl::createContext(co);
        }
        const char* threads = std::getenv("LP_NUM_THREADS");
        const std::string subtitle = ctx->info().renderer + ", LP_NUM_THREADS=" + (threads ? threads : "unset") + ", " +
                                     std::to_string(o.size) + "x" + std::to_string(o.size);
        std::cout << "prism_bench_rain: " << subtitle << "\n";
        if (trade) {
            tradeOptions.out = o.out;
            return prism::rain::bench::runRainTrade(tradeOptions);
        }
        const auto start = Clock::now();
        const std::vector<Row> rows = measureCounts(o, start);
        if (rows.empty()) return 0;
        printTables(rows);
        std::filesystem::create_directories(o.out);
        const auto csv = std::filesystem::path(o.out) / "rain_bench.csv";
        const auto svg = std::filesystem::path(o.out) / "rain_bench.svg";
        writeCsv(csv, rows);
        writeSvg(svg, rows, subtitle);
        std::cout << "\nstreak texture array: 450 layers x 16 x 64 RGBA8 (each texel holds its 4 neighbouring bins) = "
                  << 450 * 16 * 64 * 4 << " bytes (once)\nwrote " << csv.string() << " and " << svg.string() << " in "
                  << fixed(msSince(start) / 1000.0, 0) << " s\n";
    } catch (const std::exception& e) {
        std::cerr << "prism_bench_rain: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
