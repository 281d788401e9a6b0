// prism_bench_hotreload: how long a module edit takes to reach the screen with hot
// reload (prism/render/shader_watcher.hpp), with inotify and with polling, in one run. On
// a temp copy of modules/ and shader_sources/, each run appends a line to a module, then a
// render loop polls the watcher and draws every job until a frame has been drawn with all
// the rebuilt programs. Reported per case and mechanism: the time from the file write to
// the new programs in the cache (the poll that swapped them: resolve, glslang validation,
// driver link of every affected program), the first frame drawn with them (Mesa compiles a
// program's code for its first draw), and the whole latency from the write to the end of
// that frame; medians and 95th percentiles, the ratio of each latency median to
// inotify's, and the targets beside them (issue 22: edit to new program, median <= 50 ms
// with inotify; issue 9: in use under 1 s).
//   prism_bench_hotreload [--runs N] [--poll-ms M] [--work-dir DIR]
// Prints a Markdown table, measured in one run of the program.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "prism/gl/gl_context.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"

namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double kTargetMs = 1000.0;       // issue 9: "under 1 s on this machine"
constexpr double kInotifyTargetMs = 50.0;  // issue 22: edit to new program, median, with inotify

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// The nearest-rank 95th percentile.
double p95(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
    return v[std::max<std::size_t>(rank, 1) - 1];
}

double ms(Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Case {
    std::string name;
    std::string module;                // edited, under modules/
    std::vector<std::string> shaders;  // drawn each frame, one variant each
};

struct Result {
    std::vector<double> newProgramMs, firstFrameMs, latencyMs;
    std::size_t programs = 0;
    int failures = 0;
};

Result runCase(const Case& c, prism::render::WatchMechanism mechanism, const fs::path& workDir, int runs, int pollMs) {
    const fs::path root = workDir / c.name.substr(0, c.name.find(' '));
    fs::remove_all(root);
    fs::create_directories(root);
    for (const char* dir : {"modules", "shader_sources"})
        fs::copy(fs::path(PRISM_SOURCE_DIR) / dir, root / dir, fs::copy_options::recursive);
    const fs::path module = root / "modules" / c.module;
    const std::string original = readFile(module);

    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    std::vector<prism::render::RenderJob> jobs;
    for (const auto& shader : c.shaders) {
        prism::render::RenderJob job;
        job.shader = shader;
        job.mesh = prism::render::meshForShader(shader, prism::render::namedMesh("sphere", 2));
        job.width = job.height = 64;
        jobs.push_back(std::move(job));
    }
    auto drawAll = [&] {
        for (const auto& job : jobs) (void)prism::render::renderImage8(cache, job);
    };
    drawAll();  // builds one program per job
    prism::render::ShaderWatchOptions options;
    options.sourceRoot = root.string();
    options.pollInterval = std::chrono::milliseconds(pollMs);
    options.mechanism = mechanism;
    prism::render::ShaderWatcher watcher(cache, options);

    Result r;
    r.programs = cache.size();
    for (int run = 0; run < runs; ++run) {
        const std::size_t before = cache.reloadCount();
        const auto start = Clock::now();
        {
            std::ofstream out(module, std::ios::binary | std::ios::trunc);
            // Text no earlier run wrote: Mesa's shader cache would otherwise make a later
            // mechanism's first frames cache hits.
            out << original << "// hot reload edit " << run << " at " << start.time_since_epoch().count() << "\n";
        }
        double newProgram = 0.0, firstFrame = 0.0;
        for (;;) {
            const auto result = watcher.poll();
            const auto drawStart = Clock::now();
            if (!result.reloaded.empty()) newProgram = ms(drawStart - start);  // the last swap of this edit
            for (const auto& d : result.diagnostics) std::cerr << d;
            drawAll();
            if (!result.reloaded.empty()) firstFrame += ms(Clock::now() - drawStart);
            if (cache.reloadCount() >= before + r.programs) break;
            if (!result.diagnostics.empty() || ms(Clock::now() - start) > 10 * kTargetMs) {
                ++r.failures;
                break;
            }
        }
        r.latencyMs.push_back(ms(Clock::now() - start));
        r.newProgramMs.push_back(newProgram);
        r.firstFrameMs.push_back(firstFrame);
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 20, pollMs = 100;
    fs::path workDir = fs::temp_directory_path() / "prism_bench_hotreload";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--runs" || a == "--poll-ms" || a == "--work-dir") && i + 1 < argc) {
            const char* v = argv[++i];
            if (a == "--runs")
                runs = std::max(1, std::atoi(v));
            else if (a == "--poll-ms")
                pollMs = std::max(0, std::atoi(v));
            else
                workDir = v;
        } else {
            std::cerr << "usage: prism_bench_hotreload [--runs N] [--poll-ms M] [--work-dir DIR]\n";
            return 2;
        }
    }
    const std::vector<Case> cases{
        {"unicolor (material.glsl edit)", "material.glsl", {"unicolor"}},
        {"phong (lighting.glsl edit)", "lighting.glsl", {"phong"}},
        {"lit (lighting.glsl edit; flat, gouraud, phong, smooth)",
         "lighting.glsl",
         {"flat", "gouraud", "phong", "smooth"}},
    };
    try {
        auto context = prism::gl::createContext();
        std::cout << "# Hot reload: module edit to new program (" << context->info().renderer << ")\n\n"
                  << runs << " runs per case and mechanism; polling every " << pollMs
                  << " ms; times in ms, medians (p95); ratios to inotify's median.\n\n"
                  << "| case | mechanism | programs rebuilt | edit to new program | ratio | target | first frame | "
                     "edit to new program in use | ratio | target |\n|---|---|---|---|---|---|---|---|---|---|\n";
        int failures = 0;
        bool overTarget = false;
        for (const auto& c : cases) {
            double inotifyNew = 0.0, inotifyInUse = 0.0;
            for (const auto mechanism :
                 {prism::render::WatchMechanism::Inotify, prism::render::WatchMechanism::Polling}) {
                const bool inotify = mechanism == prism::render::WatchMechanism::Inotify;
                const auto r = runCase(c, mechanism, workDir, runs, pollMs);
                const double newMedian = median(r.newProgramMs), inUseMedian = median(r.latencyMs);
                if (inotify) inotifyNew = newMedian, inotifyInUse = inUseMedian;
                overTarget = overTarget || (inotify && newMedian > kInotifyTargetMs) || p95(r.latencyMs) >= kTargetMs;
                failures += r.failures;
                std::cout << std::fixed << std::setprecision(1) << "| " << c.name << " | "
                          << (inotify ? "inotify" : "polling") << " | " << r.programs << " | " << newMedian << " ("
                          << p95(r.newProgramMs) << ") | " << newMedian / inotifyNew << " | "
                          << (inotify ? "<= " + std::to_string(int(kInotifyTargetMs)) : std::string("-")) << " | "
                          << median(r.firstFrameMs) << " (" << p95(r.firstFrameMs) << ") | " << inUseMedian << " ("
                          << p95(r.latencyMs) << ") | " << inUseMedian / inotifyInUse << " | < " << kTargetMs << " |\n";
            }
        }
        if (failures > 0) {
            std::cerr << "prism_bench_hotreload: " << failures << " run(s) did not reload\n";
            return 1;
        }
        std::cout << "\n"
                  << (overTarget ? "Some figures missed their target." : "Every figure met its target.") << "\n";
    } catch (const std::exception& e) {
        std::cerr << "prism_bench_hotreload: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
