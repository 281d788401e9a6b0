// The rain trade of prism_bench_rain --trade (see rain_trade.hpp).
#include "rain_trade.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/reference/pareto.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/rain/rain_system.hpp"
#include "trade_plot.hpp"

namespace prism::rain::bench {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kBands = 4;           // distance bands of R / 4, the default rings
constexpr float kFrameStep = 0.1f;  // s of rain between averaged frames
// Every layer is scaled to this many particles per drop (the default), so that settings of
// any density compare at the light the default draws.
constexpr double kCommonPpd = 0.05;

struct Setting {
    StreakTechnique technique = StreakTechnique::GeometryShader;
    double ppd = 0.05;  // particles per drop
    int rings = 4;
    float falloff = 0.5f;
};

struct Outcome {
    Setting s;
    std::uint32_t particles = 0;
    double frameMs = 0.0;                // median update + draw
    std::vector<double> layer;           // time-averaged light added per pixel, 8-bit units, at kCommonPpd
    double meanErr = 0.0, p95Err = 0.0;  // |layer - reference|
    double lightBias = 0.0;              // (sum layer - sum reference) / sum reference
    double density[kBands] = {};         // particles per m^3 per band / the full-rate density
    bool front = false;
};

const char* streakLabel(StreakTechnique t) {
    return t == StreakTechnique::GeometryShader ? "gs" : t == StreakTechnique::Instanced ? "instanced" : "points";
}

std::string fmt(double v, int precision) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

std::string name(const Setting& s) {
    return std::string(streakLabel(s.technique)) + " ppd " + fmt(s.ppd, 4) +
           (s.rings == 1 ? std::string(" no LOD") : " LOD " + std::to_string(s.rings) + "x" + fmt(s.falloff, 2));
}

RainParams paramsFor(const Setting& s) {
    RainParams p;  // moderate rain, the default cylinder
    p.particlesPerDrop = static_cast<float>(s.ppd);
    p.lodRings = s.rings;
    p.lodFalloff = s.falloff;
    p.budget = kMaxParticles;
    p.wind.strength = 3.0f;
    p.seed = 2013;
    return p;
}

// Particles per m^3 in each band of horizontal distance from the eye, over the density
// the rain has without LOD (particlesPerDrop N / v).
void measureDensity(Outcome& r, const RainSystem& rain, const RainParams& p, const glm::vec3& eye) {
    double count[kBands] = {};
    for (const Particle& q : rain.readParticles()) {
        const float d = std::hypot(q.position.x - eye.x, q.position.z - eye.z);
        const int band = static_cast<int>(d / (p.radius / kBands));
        if (band >= 0 && band < kBands) count[band] += 1.0;
    }
    const double full = p.particlesPerDrop * rainRateFor(p.intensity).dropsPerCubicMetre();
    for (int k = 0; k < kBands; ++k) {
        const double ring = p.radius / kBands;
        const double volume = M_PI * ring * ring * (2 * k + 1) * p.height;
        r.density[k] = count[k] / volume / full;
    }
}

Outcome run(RainPrograms& programs, const Setting& s, int frames, const RainTradeOptions& o) {
    Outcome r;
    r.s = s;
    const RainParams p = paramsFor(s);
    const view::Camera camera = rainSceneView(0);
    RainSystem rain(programs, p, camera.eye);
    r.particles = rain.particleCount();
    gl::Framebuffer fb(o.size, o.size, gl::ColorFormat::Rgba32F);
    RainDrawInputs in;
    in.camera = camera;
    in.viewportHeight = o.size;
    in.technique = s.technique;
    r.layer.assign(static_cast<std::size_t>(o.size) * o.size, 0.0);
    std::vector<double> ms;
    const double scale = 255.0 / 3.0 * kCommonPpd / s.ppd / frames;  // mean of R, G, B in 8-bit units
    for (int f = 0; f < frames; ++f) {
        fb.clear({0.0f, 0.0f, 0.0f, 0.0f});
        glFinish();
        const auto start = Clock::now();
        rain.update(kFrameStep, camera.eye);
        rain.draw(in);
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        const image::ImageF img = fb.readImageF();
        for (std::size_t i = 0; i < r.layer.size(); ++i)
            r.layer[i] += (img.data[4 * i] + img.data[4 * i + 1] + img.data[4 * i + 2]) * scale;
    }
    std::sort(ms.begin(), ms.end());
    r.frameMs = ms[ms.size() / 2];
    measureDensity(r, rain, p, camera.eye);
    return r;
}

void compare(Outcome& r, const Outcome& ref) {
    std::vector<double> diff(r.layer.size());
    double sum = 0.0, mine = 0.0, theirs = 0.0;
    for (std::size_t i = 0; i < diff.size(); ++i) {
        diff[i] = std::abs(r.layer[i] - ref.layer[i]);
        sum += diff[i];
        mine += r.layer[i];
        theirs += ref.layer[i];
    }
    r.meanErr = sum / static_cast<double>(diff.size());
    const std::size_t k = diff.size() * 95 / 100;
    std::nth_element(diff.begin(), diff.begin() + static_cast<std::ptrdiff_t>(k), diff.end());
    r.p95Err = diff[k];
    r.lightBias = (mine - theirs) / theirs;
}

std::vector<Setting> settings() {
    std::vector<Setting> list;
    const std::pair<int, float> lods[] = {{1, 1.0f}, {2, 0.5f}, {4, 0.5f}, {4, 0.75f}, {8, 0.5f}};
    for (double ppd : {0.0125, 0.025, 0.05, 0.1})
        for (auto [rings, falloff] : lods) list.push_back({StreakTechnique::GeometryShader, ppd, rings, falloff});
    for (StreakTechnique t : {StreakTechnique::Instanced, StreakTechnique::PointSprites})
        for (double ppd : {0.025, 0.05, 0.1}) list.push_back({t, ppd, 4, 0.5f});
    return list;
}

void printTable(const std::vector<Outcome>& rows) {
    std::cout
        << "\n| setting | particles | frame ms | light err mean | light err p95 | light bias (%) | density 0-6 m | "
           "6-12 m | 12-19 m | 19-25 m | front |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (const Outcome& r : rows) {
        std::cout << "| " << name(r.s) << " | " << r.particles << " | " << fmt(r.frameMs, 1) << " | "
                  << fmt(r.meanErr, 3) << " | " << fmt(r.p95Err, 3) << " | " << fmt(r.lightBias * 100.0, 1);
        for (double d : r.density) std::cout << " | " << fmt(d, 2);
        std::cout << " | " << (r.front ? "**yes**" : "") << " |\n";
    }
}

void writeCsv(const std::filesystem::path& path, const std::vector<Outcome>& rows) {
    std::ofstream f(path);
    f << "setting,technique,particles_per_drop,lod_rings,lod_falloff,particles,frame_ms,light_err_mean,light_err_p95,"
         "light_bias,density_band0,density_band1,density_band2,density_band3,pareto\n";
    for (const Outcome& r : rows) {
        f << name(r.s) << "," << streakLabel(r.s.technique) << "," << r.s.ppd << "," << r.s.rings << "," << r.s.falloff
          << "," << r.particles << "," << r.frameMs << "," << r.meanErr << "," << r.p95Err << "," << r.lightBias;
        for (double d : r.density) f << "," << d;
        f << "," << (r.front ? 1 : 0) << "\n";
    }
}

}  // namespace

namespace {

// RainCL §4.1.2 puts fewer particles in the outer rings so that "it seems to rain in the
// whole visible area" at a lower cost: per particle density, what the default rings save
// and what they lose against the same density without LOD.
void checkLod(const std::vector<Outcome>& rows) {
    std::cout << "\nLOD 4x0.50 against no LOD (GS, same particles per drop):\n";
    for (const Outcome& lod : rows) {
        if (lod.s.technique != StreakTechnique::GeometryShader || lod.s.rings != 4 || lod.s.falloff != 0.5f) continue;
        for (const Outcome& none : rows)
            if (none.s.technique == lod.s.technique && none.s.ppd == lod.s.ppd && none.s.rings == 1)
                std::cout << "  ppd " << fmt(lod.s.ppd, 4) << ": " << fmt(100.0 * lod.particles / none.particles, 0)
                          << " % of the particles, " << fmt(100.0 * lod.frameMs / none.frameMs, 0)
                          << " % of the frame time; light error " << fmt(none.meanErr, 3) << " -> "
                          << fmt(lod.meanErr, 3) << ", light bias " << fmt(none.lightBias * 100.0, 1) << " % -> "
                          << fmt(lod.lightBias * 100.0, 1) << " %\n";
    }
}

// The default (GS, 0.05 particles per drop, LOD 4x0.5) against the cheapest setting that is
// at least as accurate and adds the reference's light within 5 %.
void recommend(const std::vector<Outcome>& rows) {
    std::vector<double> cost, error;
    std::vector<std::size_t> unbiased;
    std::size_t current = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        cost.push_back(rows[i].frameMs);
        error.push_back(rows[i].meanErr);
        if (std::abs(rows[i].lightBias) <= 0.05) unbiased.push_back(i);
        const Setting& s = rows[i].s;
        if (s.technique == StreakTechnique::GeometryShader && s.ppd == 0.05 && s.rings == 4 && s.falloff == 0.5f)
            current = i;
    }
    const auto same = reference::cheapestWithin(cost, error, error[current]);
    const auto fair = reference::cheapestWithin(cost, error, error[current], unbiased);
    std::cout << "\ncurrent default: " << name(rows[current].s) << ", " << fmt(rows[current].frameMs, 1)
              << " ms, light error " << fmt(error[current], 3) << ", bias " << fmt(rows[current].lightBias * 100, 1)
              << " %\ncheapest at least as accurate: " << (same ? name(rows[*same].s) : "none")
              << "\nrecommended (at least as accurate, light within 5 % of the reference): "
              << (fair ? name(rows[*fair].s) + ", " + fmt(rows[*fair].frameMs, 1) + " ms" : "none") << "\n";
}

// The most accurate setting whose frame costs at most `budgetMs` (e.g. an earlier build's default's frame).
void bestWithinBudget(const std::vector<Outcome>& rows, double budgetMs) {
    const Outcome* best = nullptr;
    for (const Outcome& r : rows)
        if (r.frameMs <= budgetMs && (!best || r.meanErr < best->meanErr)) best = &r;
    std::cout << "most accurate within " << fmt(budgetMs, 1) << " ms a frame: "
              << (best ? name(best->s) + ", " + fmt(best->frameMs, 1) + " ms, light error " + fmt(best->meanErr, 3) +
                             ", bias " + fmt(best->lightBias * 100.0, 1) + " %"
                       : std::string("none"))
              << "\n";
}

void writeSvg(const std::filesystem::path& path, const std::vector<Outcome>& rows, const RainTradeOptions& o) {
    std::vector<prism::bench::TradePoint> points;
    for (const Outcome& r : rows) {
        const std::string lod =
            r.s.rings == 1 ? "no LOD" : "LOD " + std::to_string(r.s.rings) + "x" + fmt(r.s.falloff, 2);
        points.push_back(
            {std::string(streakLabel(r.s.technique)) + ", " + lod, name(r.s), r.frameMs, r.meanErr, r.front});
    }
    prism::bench::writeTradeSvg(
        path, points,
        {"Rain: frame time against the error of the time-averaged rain layer",
         "view 0, " + std::to_string(o.size) + "x" + std::to_string(o.size) + ", moderate rain, " +
             std::to_string(o.frames) + " frames; reference: GS, no LOD, " + fmt(o.referencePpd, 2) + " per drop, " +
             std::to_string(o.referenceFrames) + " frames",
         "ms per frame (update + draw)", "mean |light added - reference| (8-bit units at 0.05 per drop)"});
}

}  // namespace

int runRainTrade(const RainTradeOptions& o) {
    RainPrograms programs;
    const Setting referenceSetting{StreakTechnique::GeometryShader, o.referencePpd, 1, 1.0f};
    const Outcome reference = run(programs, referenceSetting, o.referenceFrames, o);
    double light = 0.0;
    for (double v : reference.layer) light += v / static_cast<double>(reference.layer.size());
    std::cout << "trade at " << o.size << "x" << o.size << "; reference: " << name(referenceSetting) << ", "
              << reference.particles << " particles, " << o.referenceFrames << " frames, " << fmt(reference.frameMs, 1)
              << " ms a frame; mean light added " << fmt(light, 3) << " (8-bit units)\n"
              << std::flush;
    std::vector<Outcome> rows;
    for (const Setting& s : settings()) {
        rows.push_back(run(programs, s, o.frames, o));
        compare(rows.back(), reference);
        std::cout << "  " << name(s) << ": " << fmt(rows.back().frameMs, 1) << " ms\n" << std::flush;
    }
    std::vector<double> cost, error;
    for (const Outcome& r : rows) cost.push_back(r.frameMs), error.push_back(r.meanErr);
    const std::vector<std::size_t> front = reference::paretoFront(cost, error);
    for (std::size_t i : front) rows[i].front = true;
    printTable(rows);
    std::cout << "\nPareto front (frame ms vs mean light error), cheapest first:";
    for (std::size_t i : front) std::cout << " " << name(rows[i].s) << ";";
    std::cout << "\n";
    checkLod(rows);
    recommend(rows);
    if (o.budgetMs > 0.0) bestWithinBudget(rows, o.budgetMs);
    std::filesystem::create_directories(o.out);
    writeCsv(std::filesystem::path(o.out) / "rain_trade.csv", rows);
    writeSvg(std::filesystem::path(o.out) / "rain_trade.svg", rows, o);
    std::cout << "wrote " << o.out << "/rain_trade.csv and rain_trade.svg\n";
    return 0;
}

}  // namespace prism::rain::bench
