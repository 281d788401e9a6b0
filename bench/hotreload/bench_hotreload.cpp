// prism_bench_hotreload: how long a module edit takes to reach the screen with hot
// reload (prism/render/shader_watcher.hpp). On a temp copy of modules/ and
// shader_sources/, each run appends a line to a module, then a render loop polls the
// watcher (at the viewer's interval) and draws every job until a frame has been drawn
// with all the rebuilt programs. Reported per case: the in-process rebuild (resolve,
// glslang validation, driver link of every affected program, i.e. the poll that swapped
// them), the first frame drawn with the new programs (Mesa compiles a program's code for
// its first draw), and the whole latency from the file write to the end of that frame,
// beside issue 9's target.
//   prism_bench_hotreload [--runs N] [--poll-ms M] [--work-dir DIR]
// Prints a Markdown table; medians and maxima of N runs, measured in one run of the program.
#include <algorithm>
#include <chrono>
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

constexpr double kTargetMs = 1000.0;  // issue 9: "under 1 s on this machine"

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
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
    std::vector<double> rebuildMs, firstFrameMs, latencyMs;
    std::size_t programs = 0;
    int failures = 0;
};

Result runCase(const Case& c, const fs::path& workDir, int runs, int pollMs) {
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
    prism::render::ShaderWatcher watcher(cache, options);

    Result r;
    r.programs = cache.size();
    for (int run = 0; run < runs; ++run) {
        const std::size_t before = cache.reloadCount();
        const auto start = Clock::now();
        {
            std::ofstream out(module, std::ios::binary | std::ios::trunc);
            out << original << "// hot reload edit " << run << "\n";
        }
        double rebuild = 0.0, firstFrame = 0.0;
        for (;;) {
            const auto pollStart = Clock::now();
            const auto result = watcher.poll();
            const auto drawStart = Clock::now();
            if (!result.reloaded.empty()) rebuild += ms(drawStart - pollStart);
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
        r.rebuildMs.push_back(rebuild);
        r.firstFrameMs.push_back(firstFrame);
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 15, pollMs = 100;
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
        std::cout << "# Hot reload: module edit to new program in use (" << context->info().renderer << ")\n\n"
                  << runs << " runs per case; the watcher polls every " << pollMs
                  << " ms; medians and maxima in ms.\n\n"
                  << "| case | programs rebuilt | rebuild (median) | first frame (median) | "
                     "edit to new program in use (median) | max | target |\n|---|---|---|---|---|---|---|\n";
        int failures = 0;
        bool overTarget = false;
        for (const auto& c : cases) {
            const auto r = runCase(c, workDir, runs, pollMs);
            const double worst = *std::max_element(r.latencyMs.begin(), r.latencyMs.end());
            overTarget = overTarget || worst >= kTargetMs;
            failures += r.failures;
            std::cout << std::fixed << std::setprecision(1) << "| " << c.name << " | " << r.programs << " | "
                      << median(r.rebuildMs) << " | " << median(r.firstFrameMs) << " | " << median(r.latencyMs) << " | "
                      << worst << " | < " << kTargetMs << " |\n";
        }
        if (failures > 0) {
            std::cerr << "prism_bench_hotreload: " << failures << " run(s) did not reload\n";
            return 1;
        }
        std::cout << "\n"
                  << (overTarget ? "Some edits took 1 s or more." : "Every edit reached the screen within 1 s.")
                  << "\n";
    } catch (const std::exception& e) {
        std::cerr << "prism_bench_hotreload: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
