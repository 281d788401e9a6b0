// prism_bench_diffraction: the diffraction shader's accuracy/speed trade (docs/diffraction.md).
// Surface: a CD-like track profile (1600 nm pitch, 500 nm wide, 110 nm deep grooves, 16 tracks).
// For each point (path a, b or c, Taylor terms N, wavelength step, table size, w slices of c) it renders
//   - the error map: view angle -80..80 deg (columns) x light incidence 0..80 deg (rows) in the
//     plane of incidence (brdf_map.frag) into RGBA32F, compared with the exact path (FFT of
//     exp(i k w h) per wavelength and direction, 1 nm steps) after a unit white light's exposure
//     (radiance = BRDF cos(theta_i), clamped, sRGB): mean and 95th percentile CIEDE2000 over the
//     lit pixels (either image above 1/255) and over all pixels, max 8-bit difference;
//   - the frame time: a 512x512 frame of a flat plate under one directional light with the
//     diffraction material, median of 7 frames on this GL driver (llvmpipe), and the same frame
//     with Phong measured right after it (the ratio, so both see the same machine load);
//   - the table memory on the GPU.
// Then prints the Pareto front (cost as the ratio to Phong vs mean lit CIEDE2000) and the recommended default:
// the fastest front point with mean lit dE2000 <= 1 and p95 <= 2 (no visible banding), beside
// the target (<= 4x Phong, mean dE <= 1).
//
//   prism_bench_diffraction [--csv diffraction_bench.csv] [--svg diffraction_bench.svg]
//                           [--frame 512] [--quick]
#include <CLI/CLI.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "prism/diffraction/colour_difference.hpp"
#include "prism/diffraction/diffraction_gl.hpp"
#include "prism/diffraction/lookup_tables.hpp"
#include "prism/diffraction/taylor_bound.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/shaders.hpp"

using namespace prism::diffraction;

namespace {

constexpr int kMapColumns = 161, kMapRows = 41;  // view -80..80 step 1, incidence 0..80 step 2
constexpr double kViewStart = -80.0, kViewStep = 1.0, kLightStart = 0.0, kLightStep = 2.0;

HeightField cdProfile() {
    HeightField f;
    const int tracks = 16, perTrack = 16;
    f.width = tracks * perTrack;
    f.height = 1;
    f.pixelNm = 1600.0 / perTrack;
    for (int x = 0; x < f.width; ++x) {
        const double inTrack = (x % perTrack + 0.5) * f.pixelNm;
        f.heightsNm.push_back(std::abs(inTrack - 800.0) <= 250.0 ? -110.0 : 0.0);
    }
    return f;
}

using RgbImage = std::vector<LinearRgb>;  // kMapColumns x kMapRows, row = incidence

Direction lightAt(int row) {
    return fromAngles(kLightStart + row * kLightStep, 180.0);
}
Direction viewAt(int column) {
    return fromAngles(kViewStart + column * kViewStep, 0.0);
}

RgbImage exactMap(const HeightField& field) {
    const StamBrdf exact(field, {.path = StamBrdf::Path::Exact});
    const std::vector<SpectralWeight> weights = spectralWeights(1);
    RgbImage image;
    for (int r = 0; r < kMapRows; ++r) {
        for (int c = 0; c < kMapColumns; ++c) image.push_back(shadeReference(exact, lightAt(r), viewAt(c), weights));
    }
    return image;
}

RgbImage gpuMap(const DiffractionTextures& textures) {
    prism::gl::Program& program = diffractionPrograms().get("brdf_map", {{"DIFFRACTION_PATH", textures.variant()}});
    prism::gl::Framebuffer target(kMapColumns, kMapRows, prism::gl::ColorFormat::Rgba32F);
    target.clear({0, 0, 0, 0});
    program.use();
    textures.apply(program);
    program.set("u_diffractionMapAngles", glm::vec4(kViewStart, kViewStep, kLightStart, kLightStep));
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDeleteVertexArrays(1, &vao);
    const prism::image::ImageF pixels = target.readImageF();  // row 0 = top = last GL row
    RgbImage image;
    for (int r = 0; r < kMapRows; ++r) {
        for (int c = 0; c < kMapColumns; ++c) {
            const auto p = pixels.at(c, kMapRows - 1 - r);
            image.push_back({p[0], p[1], p[2]});
        }
    }
    return image;
}

struct Error {
    double meanLit = 0, p95Lit = 0, meanAll = 0, p95All = 0;
    int max8bit = 0;
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(std::min<double>(v.size() - 1, std::floor(q * v.size())))];
}

Error compare(const RgbImage& exact, const RgbImage& approx) {
    std::vector<double> lit, all;
    Error e;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        const double cosI = lightAt(static_cast<int>(i) / kMapColumns).z;
        const auto expose = [cosI](LinearRgb c) {
            return LinearRgb{std::clamp(c.r * cosI, 0.0, 1.0), std::clamp(c.g * cosI, 0.0, 1.0),
                             std::clamp(c.b * cosI, 0.0, 1.0)};
        };
        const LinearRgb a = expose(exact[i]), b = expose(approx[i]);
        const double de = ciede2000(linearSrgbToLab(a), linearSrgbToLab(b));
        all.push_back(de);
        const int a8[3] = {int(std::lround(255 * srgbEncode(a.r))), int(std::lround(255 * srgbEncode(a.g))),
                           int(std::lround(255 * srgbEncode(a.b)))};
        const int b8[3] = {int(std::lround(255 * srgbEncode(b.r))), int(std::lround(255 * srgbEncode(b.g))),
                           int(std::lround(255 * srgbEncode(b.b)))};
        bool isLit = false;
        for (int k = 0; k < 3; ++k) {
            e.max8bit = std::max(e.max8bit, std::abs(a8[k] - b8[k]));
            isLit = isLit || a8[k] > 0 || b8[k] > 0;
        }
        if (isLit) lit.push_back(de);
    }
    const auto mean = [](const std::vector<double>& v) {
        double s = 0;
        for (double x : v) s += x;
        return v.empty() ? 0.0 : s / v.size();
    };
    e.meanLit = mean(lit), e.p95Lit = percentile(lit, 0.95), e.meanAll = mean(all), e.p95All = percentile(all, 0.95);
    return e;
}

// The timed scene: a flat plate filling the frame, one directional light.
struct Scene {
    prism::geometry::Mesh mesh = prism::geometry::makeGrid(4.0f, 4.0f, 8, 8);
    prism::view::Camera camera;
    prism::view::Lights lights;
    prism::view::Material material;
    Scene() {
        camera.eye = {0.0f, 1.6f, 1.2f};
        camera.target = {0.0f, 0.0f, 0.0f};
        lights.directional.push_back({glm::normalize(glm::vec3(0.6f, -1.0f, -0.4f)), glm::vec3(1.0f)});
        lights.ambient = glm::vec3(0.05f);
    }
};

double medianFrameMs(prism::gl::Program& program, const prism::render::GpuMesh& mesh,
                     const prism::gl::Framebuffer& target, int frames) {
    std::vector<double> ms;
    for (int f = 0; f < frames + 1; ++f) {  // first frame is a warm-up
        target.clear({0, 0, 0, 1});
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        program.use();
        mesh.draw();
        glFinish();
        const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (f > 0) ms.push_back(t);
        if (f == 0 && t > 2000.0) {  // slow point: one timed frame is enough
            ms.push_back(t);
            break;
        }
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

struct Point {
    char path = 'a';
    int terms = 0, stepNm = 5, size = 256, slices = 0;  // slices: path c only
    Error error;
    double frameMs = 0, phongMs = 0, ratio = 0;
    std::size_t bytes = 0;
    bool pareto = false;
};

void writeSvg(const std::string& path, const std::vector<Point>& points) {
    std::ofstream svg(path);
    const double w = 640, h = 400, left = 60, bottom = 350, top = 20, right = 620;
    double tMin = 1e9, tMax = 0, eMax = 0;
    for (const Point& p : points)
        tMin = std::min(tMin, p.ratio), tMax = std::max(tMax, p.ratio), eMax = std::max(eMax, p.error.meanLit);
    tMin = std::min(tMin, 1.0);
    const double lx0 = std::log10(tMin) - 0.1, lx1 = std::log10(tMax) + 0.1;
    const double ly0 = -2.0, ly1 = std::log10(std::max(eMax, 1.0)) + 0.2;  // dE on a log axis from 0.01
    const auto X = [&](double ms) { return left + (std::log10(ms) - lx0) / (lx1 - lx0) * (right - left); };
    const auto Y = [&](double de) {
        return bottom - (std::log10(std::max(de, 0.01)) - ly0) / (ly1 - ly0) * (bottom - top);
    };
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
        << "' font-family='sans-serif' font-size='11'>\n";
    svg << "<rect width='100%' height='100%' fill='white'/>\n";
    svg << "<line x1='" << left << "' y1='" << bottom << "' x2='" << right << "' y2='" << bottom
        << "' stroke='black'/>\n";
    svg << "<line x1='" << left << "' y1='" << top << "' x2='" << left << "' y2='" << bottom << "' stroke='black'/>\n";
    svg << "<text x='" << (left + right) / 2 - 120 << "' y='" << h - 12
        << "'>cost: frame time / Phong frame time (512x512, llvmpipe, log)</text>\n";
    svg << "<text x='12' y='" << top + 10 << "'>mean dE2000 (lit, log)</text>\n";
    for (int d = static_cast<int>(std::ceil(lx0)); d <= lx1; ++d) {
        svg << "<text x='" << X(std::pow(10, d)) - 8 << "' y='" << bottom + 14 << "'>" << std::pow(10, d)
            << "</text>\n";
    }
    for (double de : {0.01, 0.1, 1.0, 10.0}) {
        if (std::log10(de) > ly1) break;
        svg << "<text x='" << left - 40 << "' y='" << Y(de) + 4 << "'>" << de << "</text>\n";
    }
    svg << "<line x1='" << left << "' y1='" << Y(1.0) << "' x2='" << right << "' y2='" << Y(1.0)
        << "' stroke='#999' stroke-dasharray='4'/>\n";
    svg << "<line x1='" << X(4.0) << "' y1='" << top << "' x2='" << X(4.0) << "' y2='" << bottom
        << "' stroke='#999' stroke-dasharray='4'/>\n";
    svg << "<text x='" << X(4.0) + 3 << "' y='" << top + 10 << "'>4x Phong</text>\n";
    for (const Point& p : points) {
        const char* colour = p.path == 'a' ? "#1f77b4" : p.path == 'b' ? "#d62728" : "#2ca02c";
        svg << "<circle cx='" << X(p.ratio) << "' cy='" << Y(p.error.meanLit) << "' r='" << (p.pareto ? 5 : 3)
            << "' fill='" << (p.pareto ? colour : "none") << "' stroke='" << colour << "'><title>path " << p.path
            << " N=" << p.terms << " step=" << p.stepNm << " size=" << p.size << "</title></circle>\n";
    }
    svg << "<text x='" << right - 170 << "' y='" << top + 30 << "' fill='#1f77b4'>path a (per wavelength)</text>\n";
    svg << "<text x='" << right - 170 << "' y='" << top + 45 << "' fill='#d62728'>path b (pre-integrated)</text>\n";
    svg << "<text x='" << right - 170 << "' y='" << top + 60 << "' fill='#2ca02c'>path c (w volume)</text>\n";
    svg << "<text x='" << right - 170 << "' y='" << top + 75 << "'>filled: Pareto front</text>\n";
    svg << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"prism_bench_diffraction: accuracy vs speed of the diffraction shader"};
    std::string csvPath = "diffraction_bench.csv", svgPath = "diffraction_bench.svg";
    int frame = 512;
    bool quick = false;
    app.add_option("--csv", csvPath, "CSV output")->capture_default_str();
    app.add_option("--svg", svgPath, "trade plot (SVG)")->capture_default_str();
    app.add_option("--frame", frame, "timed frame size in pixels")->capture_default_str()->check(CLI::Range(16, 2048));
    app.add_flag("--quick", quick, "a few points only (smoke run)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    auto context = prism::gl::createContext();
    const HeightField field = cdProfile();
    HeightField centred = field;
    subtractMean(centred);
    const int autoTerms = termsForTolerance(maxAbsHeight(centred), kLambdaMinNm, 1e-6);
    std::printf(
        "# surface: CD track profile, 1600 nm pitch, 110 nm deep; max |h - mean| = %.1f nm; bound -> N = %d (1e-6)\n",
        maxAbsHeight(centred), autoTerms);
    std::printf("# exact reference map (%d x %d, 1 nm, FFT of exp(ikwh) per pixel and wavelength)...\n", kMapColumns,
                kMapRows);
    const RgbImage exact = exactMap(field);

    Scene scene;
    const prism::render::GpuMesh plate(scene.mesh, prism::shaders::kCatalog.contractAttributes);
    const prism::gl::Framebuffer target(frame, frame);
    prism::render::ProgramCache phongCache(prism::shaders::kCatalog);
    prism::gl::Program& phong =
        phongCache.get("phong", {{"BLINN", "0"}, {"FOG", "0"}, {"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "0"}});
    target.bind();
    prism::render::setFrameUniforms(phong, scene.camera, 1.0f, scene.lights, glm::mat4(1.0f), scene.material);
    const int frames = quick ? 3 : 7;
    const double phongMs = medianFrameMs(phong, plate, target, frames);

    std::vector<Point> points;
    const auto addPoint = [&](char path, int terms, int step, int size, int slices = 0) {
        for (const Point& p : points) {
            if (p.path == path && p.terms == terms && p.stepNm == step && p.size == size && p.slices == slices) return;
        }
        const StamBrdf brdf(field, {.terms = terms});
        const SpectralTables spectral = buildSpectralTables(brdf, {.size = size, .wavelengthStepNm = step});
        std::unique_ptr<DiffractionTextures> textures;
        if (path == 'a') {
            textures = std::make_unique<DiffractionTextures>(spectral);
        } else if (path == 'b') {
            textures = std::make_unique<DiffractionTextures>(buildIntegratedTables(spectral));
        } else {
            textures =
                std::make_unique<DiffractionTextures>(buildVolumeTables(buildIntegratedTables(spectral), slices));
        }
        Point p;
        p.path = path, p.terms = terms, p.stepNm = step, p.size = size, p.slices = slices;
        p.error = compare(exact, gpuMap(*textures));
        prism::gl::Program& program = diffractionPrograms().get(
            "diffraction",
            {{"DIFFRACTION_PATH", textures->variant()}, {"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "0"}});
        target.bind();
        prism::render::setFrameUniforms(program, scene.camera, 1.0f, scene.lights, glm::mat4(1.0f), scene.material);
        program.set("u_diffractionTangent", glm::vec3(1.0f, 0.0f, 0.0f));
        textures->apply(program);
        p.frameMs = medianFrameMs(program, plate, target, frames);
        // Phong again right after, so that the ratio compares frames taken under the same load
        // (the machine is shared); the ratio is to the mean of the run-start and adjacent Phong.
        target.bind();
        prism::render::setFrameUniforms(phong, scene.camera, 1.0f, scene.lights, glm::mat4(1.0f), scene.material);
        p.phongMs = medianFrameMs(phong, plate, target, frames);
        p.ratio = p.frameMs / p.phongMs;
        p.bytes = textures->bytes();
        std::printf(
            "  path %c N=%2d step=%2d nm size=%4d K=%2d: mean dE %.3f (p95 %.3f) | all %.3f (p95 %.3f) | max8 %3d | "
            "%8.2f ms (%7.2fx Phong at %5.2f ms) | %8.2f MiB\n",
            p.path, p.terms, p.stepNm, p.size, p.slices, p.error.meanLit, p.error.p95Lit, p.error.meanAll,
            p.error.p95All, p.error.max8bit, p.frameMs, p.ratio, p.phongMs, p.bytes / 1048576.0);
        std::fflush(stdout);
        points.push_back(p);
    };
    std::printf(
        "# Phong, same frame, at the start: %.2f ms (median of %d; each point is timed against Phong right after "
        "it)\n# sweeps around N = %d, 5 nm, 256^2:\n",
        phongMs, frames, autoTerms);
    const std::vector<int> termsSweep =
        quick ? std::vector<int>{2, autoTerms} : std::vector<int>{1, 2, 4, 6, 8, 12, 16, 20, 25, 30};
    const std::vector<int> stepSweep = quick ? std::vector<int>{5, 20} : std::vector<int>{1, 2, 5, 10, 20};
    const std::vector<int> sizeSweep = quick ? std::vector<int>{64, 256} : std::vector<int>{64, 128, 256, 512, 1024};
    for (int size : quick ? std::vector<int>{256} : std::vector<int>{256, 512, 1024}) {
        for (int slices : {8, 16, 32}) addPoint('c', autoTerms, 5, size, slices);
    }
    if (!quick) {
        for (int n : {3, 6}) addPoint('c', n, 5, 1024, 16);
    }
    for (char path : {'b', 'a'}) {
        for (int n : termsSweep) addPoint(path, n, 5, 256);
        for (int s : stepSweep) addPoint(path, autoTerms, s, 256);
        for (int size : sizeSweep) addPoint(path, autoTerms, 5, size);
    }
    // A few cheap combinations of the cheap settings, for the front.
    if (!quick) {
        for (int n : {1, 2, 3, 4}) {
            for (int size : {512, 1024}) addPoint('b', n, 5, size);
        }
        for (int n : {6, 8, 12}) {
            for (int s : {10, 20}) addPoint('b', n, s, 512);
            addPoint('b', n, 5, 512);
            addPoint('b', n, 10, 1024);
        }
    }
    // Pareto front: no other point is both faster and at most as wrong.
    for (Point& p : points) {
        p.pareto = std::none_of(points.begin(), points.end(), [&](const Point& q) {
            return (q.ratio <= p.ratio && q.error.meanLit < p.error.meanLit) ||
                   (q.ratio < p.ratio && q.error.meanLit <= p.error.meanLit);
        });
    }
    std::vector<Point> front;
    for (const Point& p : points) {
        if (p.pareto) front.push_back(p);
    }
    std::sort(front.begin(), front.end(), [](const Point& a, const Point& b) { return a.ratio < b.ratio; });
    std::printf(
        "\n# Pareto front (cost as a ratio to Phong vs mean lit dE2000)\n| path | N | step nm | table | K | mean dE | "
        "p95 dE | max 8-bit | ms | x Phong | MiB |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Point& p : front) {
        std::printf("| %c | %d | %d | %d^2 | %s | %.3f | %.3f | %d | %.2f | %.2f | %.2f |\n", p.path, p.terms, p.stepNm,
                    p.size, p.slices ? std::to_string(p.slices).c_str() : "-", p.error.meanLit, p.error.p95Lit,
                    p.error.max8bit, p.frameMs, p.ratio, p.bytes / 1048576.0);
    }
    const Point* best = nullptr;
    for (const Point& p : front) {
        if (p.error.meanLit <= 1.0 && p.error.p95Lit <= 2.0 && (!best || p.ratio < best->ratio)) best = &p;
    }
    if (best) {
        std::printf(
            "\n# recommended default: path %c, N = %d, %d nm, %d^2 tables%s: mean dE2000 %.3f (target <= 1), %.2f ms = "
            "%.2fx Phong (target <= 4x) %s\n",
            best->path, best->terms, best->stepNm, best->size,
            best->slices ? (", " + std::to_string(best->slices) + " w slices").c_str() : "", best->error.meanLit,
            best->frameMs, best->ratio, best->ratio <= 4.0 ? "MET" : "NOT MET");
    } else {
        std::printf("\n# no point reaches mean dE2000 <= 1 with p95 <= 2\n");
    }
    std::ofstream csv(csvPath);
    csv << "path,terms,step_nm,table_size,slices,mean_de_lit,p95_de_lit,mean_de_all,p95_de_all,max_8bit,frame_ms,phong_"
           "ms,ratio_phong,table_bytes,pareto\n";
    for (const Point& p : points) {
        csv << p.path << ',' << p.terms << ',' << p.stepNm << ',' << p.size << ',' << p.slices << ',' << p.error.meanLit
            << ',' << p.error.p95Lit << ',' << p.error.meanAll << ',' << p.error.p95All << ',' << p.error.max8bit << ','
            << p.frameMs << ',' << p.phongMs << ',' << p.ratio << ',' << p.bytes << ',' << (p.pareto ? 1 : 0) << '\n';
    }
    writeSvg(svgPath, points);
    std::printf("# wrote %s and %s\n", csvPath.c_str(), svgPath.c_str());
    return 0;
}
