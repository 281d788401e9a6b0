// prism_bench_tradeoffs: the speed/accuracy trade of the lit catalogue shaders. Renders
// an icosphere (subdivision levels --min-level..--max-level) with flat, smooth, gouraud
// and phong on the GL context (llvmpipe here), times full frames, and measures the
// error of every image against the EXACT sphere lit per pixel on the CPU in double
// precision (prism/reference/sphere_reference.hpp). Prints a Markdown report (table, Pareto front,
// error budgets, Gouraud vs Phong per level, reference validation) and writes
// OUT/tradeoffs.csv and OUT/tradeoffs.svg.
//
//     prism_bench_tradeoffs --out docs/ [--size 512] [--frames 60] [--warmup 2] [--burst 3]
//                           [--min-level 0] [--max-level 6] [--shaders flat,smooth,gouraud,phong]
//                           [--images DIR] [--backend egl|osmesa]
//
// Timing: every (shader, level) has its mesh uploaded once (GpuMesh) and its program
// built before timing. One frame = bind + clear colour and depth of a --size square
// RGBA8 framebuffer, drawJob() (uniforms + one glDrawElements), glFinish(); wall time by
// steady_clock, plus the process CPU time (all threads) of the same interval. Frames
// are taken in rounds over all configurations, each round in a new random order, so a
// change in machine load hits all of them alike; a visit draws --burst frames in a
// row and drops the first, which pays for releasing the previous configuration's
// scene (measured: a cheap frame right after an 80k-triangle one took 2-3 ms longer).
// The first --warmup rounds are dropped. Reported: median and minimum (and p25/p75 in
// the CSV) of the --frames kept frames.
//
// Scene: the repository's default camera and lights (prism::render::defaultCamera/Lights) and a
// material chosen so that no reference pixel clamps (checked and printed), because a
// clamped highlight would hide its error; background cleared with alpha 0 so coverage
// is read back from alpha (every lit shader writes alpha 1).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "prism/reference/image_metrics.hpp"
#include "prism/image/contact_sheet.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"
#include "prism/reference/sphere_reference.hpp"
#include "tradeoff_report.hpp"

namespace {

using namespace prism;
using namespace prism::bench;
using namespace prism::reference;
using namespace prism::render;
using namespace prism::image;
using namespace prism::view;
using Clock = std::chrono::steady_clock;

struct Options {
    std::string out = ".";
    int size = 512;
    int frames = 60;
    int warmup = 2;
    int burst = 3;
    unsigned minLevel = 0;
    unsigned maxLevel = 6;
    std::vector<std::string> shaders{"flat", "smooth", "gouraud", "phong"};
    std::string images;
    std::string backend;
};

struct Config {
    Row row;
    RenderJob job;  // drawJob() reads shader, camera, lights, material, world and size; the mesh is in `gpu`
    std::unique_ptr<GpuMesh> gpu;
    std::vector<double> times;     // wall ms per frame
    std::vector<double> cpuTimes;  // process CPU ms per frame (all threads: the app's and llvmpipe's)
    Image8 image;
};

Material benchMaterial() {
    Material m;
    m.color = {0.7f, 0.45f, 0.3f, 1.0f};
    m.shininess = 32.0f;
    m.specular = 0.3f;
    return m;
}

bool isDiffuseOnly(const std::string& shader) {
    return shader == "flat" || shader == "smooth";
}

double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    const double pos = q * static_cast<double>(v.size() - 1);
    const std::size_t i = static_cast<std::size_t>(pos);
    const double f = pos - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1.0 - f) + v[i + 1] * f : v[i];
}

std::string firstLineWith(const char* file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    return "?";
}

// CPU time of the whole process (every thread, llvmpipe's workers included), ms.
double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

std::string f2(double v, int digits = 2) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

// Per budget: the fastest row within it, and the fastest that also puts the highlight
// within kHighlightBudgetPx of the reference's.
constexpr double kHighlightBudgetPx = 2.0;

void printBudgets(std::ostream& out, const std::vector<Row>& rows, const ErrorOf& error,
                  const std::vector<double>& budgets) {
    auto describe = [&](std::optional<std::size_t> best) {
        if (!best) return std::string("none measured | - | - | -");
        const Row& r = rows[*best];
        return rowName(r) + " | " + f2(r.medianMs) + " | " + f2(error(r)) + " | " + f2(r.full.highlightError, 1);
    };
    out << "| mean-error budget (8-bit) | fastest choice | median ms | mean err | highlight err px "
           "| fastest with highlight err <= "
        << kHighlightBudgetPx << " px too | median ms | mean err | highlight err px |\n"
        << "|---:|---|---:|---:|---:|---|---:|---:|---:|\n";
    for (double b : budgets) {
        std::vector<std::size_t> sharp;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (rows[i].full.highlightFound && rows[i].full.highlightError <= kHighlightBudgetPx) sharp.push_back(i);
        const auto any = cheapestWithin(rows, error, b);
        const auto withHighlight = sharp.empty() ? std::nullopt : cheapestWithin(rows, error, b, sharp);
        out << "| <= " << b << " | " << describe(any) << " | " << describe(withHighlight) << " |\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"prism_bench_tradeoffs: frame time vs error against the exact sphere, per shader and mesh level"};
    app.add_option("--out", o.out, "directory for tradeoffs.csv and tradeoffs.svg")->capture_default_str();
    app.add_option("--size", o.size, "framebuffer width and height")
        ->capture_default_str()
        ->check(CLI::Range(16, 4096));
    app.add_option("--frames", o.frames, "timed frames per configuration")
        ->capture_default_str()
        ->check(CLI::Range(1, 100000));
    app.add_option("--warmup", o.warmup, "untimed rounds first")->capture_default_str()->check(CLI::Range(0, 1000));
    app.add_option("--burst", o.burst, "frames in a row per visit; the first is not kept")
        ->capture_default_str()
        ->check(CLI::Range(2, 1000));
    app.add_option("--min-level", o.minLevel, "coarsest icosphere level")
        ->capture_default_str()
        ->check(CLI::Range(0, 7));
    app.add_option("--max-level", o.maxLevel, "finest icosphere level")->capture_default_str()->check(CLI::Range(0, 7));
    app.add_option("--shaders", o.shaders, "lit catalogue shaders to compare")->delimiter(',')->capture_default_str();
    app.add_option("--images", o.images, "also write the renders and references as PNG into this directory");
    app.add_option("--backend", o.backend, "egl|osmesa (default: egl, else osmesa)");
    CLI11_PARSE(app, argc, argv);
    if (o.minLevel > o.maxLevel) {
        std::cerr << "prism_bench_tradeoffs: --min-level is above --max-level\n";
        return 2;
    }

    try {
        auto context = o.backend.empty() ? gl::createContext() : gl::createContext(gl::parseBackend(o.backend).value());
        const std::string loadBefore = loadAverage();
        const auto started = Clock::now();

        // The reference images (CPU, double precision).
        SphereScene scene;
        scene.camera = defaultCamera();
        scene.lights = defaultLights();
        scene.material = benchMaterial();
        scene.width = scene.height = o.size;
        const glm::vec4 background{0.05f, 0.06f, 0.08f, 0.0f};  // alpha 0: "not covered"
        scene.background = glm::dvec3(background.r, background.g, background.b);
        const SphereReference fullRef = renderSphereReference(scene, true);
        const SphereReference diffuseRef = renderSphereReference(scene, false);

        // One configuration per shader x level, meshes uploaded once, programs built now.
        ProgramCache cache(shaders::kCatalog);
        std::vector<Config> configs;
        for (const auto& shader : o.shaders) {
            cache.get(shader);
            for (unsigned level = o.minLevel; level <= o.maxLevel; ++level) {
                Config c;
                const geometry::Mesh mesh = meshForShader(shader, namedMesh("icosphere", level));
                c.gpu = std::make_unique<GpuMesh>(mesh, shaders::kCatalog.contractAttributes);
                c.job.shader = shader;
                c.job.camera = scene.camera;
                c.job.lights = scene.lights;
                c.job.material = scene.material;
                c.job.width = c.job.height = o.size;
                c.job.background = background;
                c.row.shader = shader;
                c.row.level = level;
                c.row.triangles = geometry::triangleCount(mesh);
                c.row.vertices = geometry::vertexCount(mesh);
                c.row.diffuseModel = isDiffuseOnly(shader);
                configs.push_back(std::move(c));
            }
        }

        gl::Framebuffer fb(o.size, o.size, gl::ColorFormat::Rgba8);
        fb.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        const std::array<float, 4> clearColour{background.r, background.g, background.b, background.a};
        struct FrameTime {
            double wallMs, cpuMs;
        };
        auto frame = [&](const Config* c) {
            const double cpu0 = processCpuMs();
            const auto t0 = Clock::now();
            fb.clear(clearColour);
            if (c) drawJob(cache, c->job, *c->gpu);
            glFinish();
            const auto t1 = Clock::now();
            return FrameTime{std::chrono::duration<double, std::milli>(t1 - t0).count(), processCpuMs() - cpu0};
        };

        // Timing in rounds: every round visits all configurations (and the empty frame,
        // index configs.size()) in a fresh random order; a visit draws --burst frames in a
        // row and keeps all but the first, which pays for the previous configuration
        // (llvmpipe releases a frame's binned scene when the next one starts).
        std::vector<double> emptyTimes, emptyCpuTimes;
        const std::size_t slots = configs.size() + 1;
        std::vector<std::size_t> order(slots);
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::mt19937 rng(20240611u);
        const int keptPerVisit = o.burst - 1;
        const int rounds = o.warmup + (o.frames + keptPerVisit - 1) / keptPerVisit;
        for (int round = 0; round < rounds; ++round) {
            std::shuffle(order.begin(), order.end(), rng);
            for (std::size_t i : order) {
                const Config* c = i < configs.size() ? &configs[i] : nullptr;
                auto& wall = c ? configs[i].times : emptyTimes;
                auto& cpu = c ? configs[i].cpuTimes : emptyCpuTimes;
                frame(c);
                for (int b = 0; b < keptPerVisit; ++b) {
                    const FrameTime t = frame(c);
                    if (round < o.warmup || static_cast<int>(wall.size()) >= o.frames) continue;
                    wall.push_back(t.wallMs);
                    cpu.push_back(t.cpuMs);
                }
            }
        }
        gl::throwIfGlError("timing frames");
        const std::string loadAfter = loadAverage();
        const double timingSeconds = std::chrono::duration<double>(Clock::now() - started).count();

        // One more frame each, read back and measured.
        std::vector<Row> rows;
        for (auto& c : configs) {
            frame(&c);
            c.image = fb.readImage8();
            c.row.frames = static_cast<int>(c.times.size());
            c.row.medianMs = quantile(c.times, 0.5);
            c.row.p25Ms = quantile(c.times, 0.25);
            c.row.p75Ms = quantile(c.times, 0.75);
            c.row.minMs = *std::min_element(c.times.begin(), c.times.end());
            c.row.medianCpuMs = quantile(c.cpuTimes, 0.5);
            c.row.full = compareWithReference(c.image, fullRef.image);
            c.row.matched = c.row.diffuseModel ? compareWithReference(c.image, diffuseRef.image) : c.row.full;
            rows.push_back(c.row);
        }
        gl::throwIfGlError("reading back");

        // Reference check: phong on the finest mesh, read back as RGBA32F (no rounding).
        const Config* finestPhong = nullptr;
        for (const auto& c : configs)
            if (c.row.shader == "phong" && c.row.level == o.maxLevel) finestPhong = &c;
        double floatMean = 0.0, floatMax = 0.0;
        std::size_t floatPixels = 0;
        if (finestPhong) {
            RenderJob job = finestPhong->job;
            job.mesh = meshForShader("phong", namedMesh("icosphere", o.maxLevel));
            const ImageF hdr = renderImageF(cache, job);
            for (int y = 0; y < o.size; ++y)
                for (int x = 0; x < o.size; ++x) {
                    const std::size_t i =
                        static_cast<std::size_t>(y) * static_cast<std::size_t>(o.size) + static_cast<std::size_t>(x);
                    if (!fullRef.covered[i] || hdr.at(x, y)[3] != 1.0f) continue;
                    for (int ch = 0; ch < 3; ++ch) {
                        const double d =
                            std::abs(255.0 * (hdr.at(x, y)[static_cast<std::size_t>(ch)] - fullRef.radiance[i][ch]));
                        floatMean += d;
                        floatMax = std::max(floatMax, d);
                    }
                    ++floatPixels;
                }
            floatMean /= 3.0 * static_cast<double>(std::max<std::size_t>(floatPixels, 1));
        }
        const double totalSeconds = std::chrono::duration<double>(Clock::now() - started).count();

        // ---- Report ----
        std::ostream& out = std::cout;
        const auto& info = context->info();
        const std::string cpu = firstLineWith("/proc/cpuinfo", "model name");
        const char* lpThreads = std::getenv("LP_NUM_THREADS");
        out << "# prism_bench_tradeoffs\n\n"
            << "- renderer: " << info.renderer << " (" << info.version << ", backend " << gl::backendName(info.backend)
            << ")\n"
            << "- machine: " << std::thread::hardware_concurrency() << " hardware threads, CPU " << cpu
            << ", LP_NUM_THREADS=" << (lpThreads ? lpThreads : "(unset)") << "\n"
            << "- load average before / after timing: " << loadBefore << " / " << loadAfter << "\n"
            << "- image " << o.size << "x" << o.size << " RGBA8; " << o.frames << " timed frames per configuration, in "
            << "visits of " << o.burst << " frames (first not kept), rounds in random order after " << o.warmup
            << " warm-up rounds; timing took " << f2(timingSeconds, 1) << " s, whole run " << f2(totalSeconds, 1)
            << " s\n"
            << "- empty frame (bind + clear + glFinish): median " << f2(quantile(emptyTimes, 0.5)) << " ms, min "
            << f2(*std::min_element(emptyTimes.begin(), emptyTimes.end())) << " ms, median CPU "
            << f2(quantile(emptyCpuTimes, 0.5)) << " ms\n"
            << "- material: colour (0.7, 0.45, 0.3), shininess 32, specular 0.3; default camera and lights\n"
            << "- reference: full model " << std::count(fullRef.covered.begin(), fullRef.covered.end(), 1)
            << " covered pixels, " << fullRef.clampedPixels << " with a channel clamped; diffuse model "
            << diffuseRef.clampedPixels << " clamped\n\n";

        out << "## Results\n\n"
            << "`ref`: the reference each row's first error columns use (diffuse-only for flat and smooth, which "
               "have no specular term; full for gouraud and phong). mean/max err: over pixels covered by the mesh "
               "OR the sphere; interior: covered by both; silhouette px: covered by exactly one. Errors are "
               "absolute R, G, B differences in 8-bit units.\n\n";
        printTable(out, rows);

        const std::vector<double> budgets{0.5, 1, 2, 5, 10};
        const auto front = paretoFront(rows, fullError);
        out << "\n## Pareto front (median frame time vs mean error against the full reference)\n\n"
            << "| choice | median ms | mean err vs full ref |\n|---|---:|---:|\n";
        for (std::size_t i : front)
            out << "| " << rowName(rows[i]) << " | " << f2(rows[i].medianMs) << " | " << f2(fullError(rows[i]))
                << " |\n";
        out << "\nCheapest choice per error budget (error against the full reference):\n\n";
        printBudgets(out, rows, fullError, budgets);

        out << "\nCoarsest mesh per shader that meets a budget against its OWN lighting model (`ref` column):\n\n"
            << "| shader |";
        for (double b : budgets) out << " <= " << b << " |";
        out << "\n|---|";
        for (std::size_t k = 0; k < budgets.size(); ++k) out << "---|";
        out << "\n";
        for (const auto& shader : o.shaders) {
            out << "| " << shader << " |";
            for (double b : budgets) {
                std::vector<std::size_t> mine;
                for (std::size_t i = 0; i < rows.size(); ++i)
                    if (rows[i].shader == shader) mine.push_back(i);
                const auto best = cheapestWithin(rows, matchedError, b, mine);
                out << " "
                    << (best ? "L" + std::to_string(rows[*best].level) + " (" + f2(rows[*best].medianMs) + " ms)" : "-")
                    << " |";
            }
            out << "\n";
        }

        // Gouraud vs Phong per level: the two claims of the FUDGE shader thesis §5.4.
        out << "\n## Gouraud vs Phong per level\n\n"
            << "| level | triangles | gouraud ms | phong ms | phong / gouraud | gouraud err | phong err | "
               "gouraud highlight err px | phong highlight err px | mean abs(gouraud - phong) | max abs(gouraud - "
               "phong) |\n"
            << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (unsigned level = o.minLevel; level <= o.maxLevel; ++level) {
            const Config *g = nullptr, *p = nullptr;
            for (const auto& c : configs) {
                if (c.row.level != level) continue;
                if (c.row.shader == "gouraud") g = &c;
                if (c.row.shader == "phong") p = &c;
            }
            if (!g || !p) continue;
            const Metrics d = compareWithReference(g->image, p->image);
            out << "| " << level << " | " << g->row.triangles << " | " << f2(g->row.medianMs) << " | "
                << f2(p->row.medianMs) << " | " << f2(p->row.medianMs / g->row.medianMs) << " | "
                << f2(g->row.full.union_.mean) << " | " << f2(p->row.full.union_.mean) << " | "
                << f2(g->row.full.highlightError, 1) << " | " << f2(p->row.full.highlightError, 1) << " | "
                << f2(d.union_.mean) << " | " << d.union_.max << " |\n";
        }

        out << "\n## Reference validation\n\n";
        for (const auto& r : rows) {
            if (r.level != o.maxLevel) continue;
            const ErrorStats& in = r.matched.interior;
            out << "- " << rowName(r) << " vs the " << (r.diffuseModel ? "diffuse" : "full") << " reference, "
                << in.pixels << " interior pixels: " << f2(100.0 * in.shareWithin(0), 1) << " % exact, "
                << f2(100.0 * in.shareWithin(1), 1) << " % within 1, " << f2(100.0 * in.shareWithin(2), 1)
                << " % within 2, " << f2(100.0 * in.shareWithin(3), 2) << " % within 3 units; mean " << f2(in.mean, 3)
                << ", max " << in.max << "; silhouette " << r.matched.renderOnly << " + " << r.matched.referenceOnly
                << " px\n";
        }
        if (finestPhong)
            out << "- phong L" << o.maxLevel << " read back as RGBA32F vs the unrounded reference, " << floatPixels
                << " interior pixels: mean " << f2(floatMean, 3) << ", max " << f2(floatMax, 3) << " (8-bit units)\n";

        std::filesystem::create_directories(o.out);
        const auto csv = std::filesystem::path(o.out) / "tradeoffs.csv";
        const auto svg = std::filesystem::path(o.out) / "tradeoffs.svg";
        writeCsv(csv, rows, front);
        writeSvg(svg, rows, front,
                 std::to_string(o.size) + "x" + std::to_string(o.size) + ", " + info.renderer + ", " +
                     std::to_string(std::thread::hardware_concurrency()) + " threads; median of " +
                     std::to_string(o.frames) + " frames");
        out << "\nwrote " << csv.string() << " and " << svg.string() << "\n";

        if (!o.images.empty()) {
            const std::filesystem::path dir(o.images);
            writePng(dir / "reference-full.png", fullRef.image);
            writePng(dir / "reference-diffuse.png", diffuseRef.image);
            std::vector<Image8> shots;
            std::vector<std::string> labels;
            for (const auto& c : configs) {
                writePng(dir / (c.row.shader + "-L" + std::to_string(c.row.level) + ".png"), c.image);
                shots.push_back(c.image);
                labels.push_back(rowName(c.row));
            }
            shots.push_back(diffuseRef.image);
            labels.push_back("reference diffuse");
            shots.push_back(fullRef.image);
            labels.push_back("reference full");
            for (auto& shot : shots)
                for (std::size_t a = 3; a < shot.data.size(); a += 4) shot.data[a] = 255;
            writePng(dir / "sheet.png",
                     composeContactSheet(shots, labels, static_cast<int>(o.maxLevel - o.minLevel + 1)));
            out << "wrote " << configs.size() + 3 << " PNG files to " << dir.string()
                << " (alpha 0 marks background, except in sheet.png)\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "prism_bench_tradeoffs: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
