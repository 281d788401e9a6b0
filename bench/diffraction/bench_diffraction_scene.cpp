// prism_bench_diffraction_scene: the diffraction trade on a whole scene (docs/diffraction.md,
// "On the CD scene"). It renders examples/scenes/diffraction_cd.json at 512x512 with several
// diffraction settings and, right after each frame, the same scene with its disc drawn by the
// Phong shader (same colour, same lights), so each ratio is taken under the same machine load.
// Per setting it prints the median frame time (7 frames after one warm-up; the tables are built
// once per material and kept by the SceneRenderer, so a frame is the draw, not the table
// build), the ratio to Phong next to the target (<= 4x), the table memory, and the colour error
// of the displayed image against a reference render: path a (per-wavelength summation) at 1 nm
// steps with 1024^2 tables and N from the 1e-6 bound, the most accurate GPU setting (on the BRDF
// map of prism_bench_diffraction it is within mean dE2000 0.14 of the exact CPU path). Error:
// mean and 95th percentile CIEDE2000 over the disc's pixels (where either image differs from
// the background), the 8-bit pixel values read as sRGB, next to the target (mean <= 1).
//
//   prism_bench_diffraction_scene [--scene FILE.json] [--size 512] [--frames 7]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "prism/diffraction/colour.hpp"
#include "prism/diffraction/colour_difference.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/shaders.hpp"

namespace {

using prism::diffraction::DiffractionMaterial;
using prism::image::Image8;

struct Setting {
    std::string label;
    char path;
    int tableSize;
    int slices;
    int stepNm;
    double tolerance;
};

struct Error {
    double mean = 0.0, p95 = 0.0;
    std::size_t pixels = 0;
};

double srgbDecode(std::uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

prism::diffraction::Lab labOf(const Image8& image, std::size_t i) {
    return prism::diffraction::linearSrgbToLab(
        {srgbDecode(image.data[i]), srgbDecode(image.data[i + 1]), srgbDecode(image.data[i + 2])});
}

Error compare(const Image8& reference, const Image8& image, const Image8& background) {
    std::vector<double> de;
    for (std::size_t i = 0; i < image.data.size(); i += 4) {
        const bool onDisc =
            !std::equal(reference.data.begin() + i, reference.data.begin() + i + 3, background.data.begin() + i) ||
            !std::equal(image.data.begin() + i, image.data.begin() + i + 3, background.data.begin() + i);
        if (onDisc) de.push_back(prism::diffraction::ciede2000(labOf(reference, i), labOf(image, i)));
    }
    Error e;
    e.pixels = de.size();
    if (de.empty()) return e;
    double sum = 0.0;
    for (double d : de) sum += d;
    e.mean = sum / static_cast<double>(de.size());
    std::sort(de.begin(), de.end());
    e.p95 = de[std::min(de.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(de.size())))];
    return e;
}

double frameMs(prism::scene::SceneRenderer& renderer, const prism::scene::Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(scene);  // ends with the read-back, so the GPU work is done
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"prism_bench_diffraction_scene: diffraction settings on a whole scene, against Phong and a reference"};
    std::string scenePath = std::string(PRISM_SOURCE_DIR) + "/examples/scenes/diffraction_cd.json";
    int size = 512, frames = 7;
    app.add_option("--scene", scenePath, "scene JSON with one diffraction object")->check(CLI::ExistingFile);
    app.add_option("--size", size, "square frame edge in pixels")->check(CLI::Range(16, 2048))->capture_default_str();
    app.add_option("--frames", frames, "timed frames per setting (median)")
        ->check(CLI::Range(1, 101))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    auto context = prism::gl::createContext(prism::gl::Backend::Egl, {.majorVersion = 4, .minorVersion = 3});
    prism::scene::Scene scene = prism::scene::loadScene(scenePath);
    scene.width = scene.height = size;
    auto disc = std::find_if(scene.objects.begin(), scene.objects.end(),
                             [](const prism::scene::SceneObject& o) { return o.diffraction.has_value(); });
    if (disc == scene.objects.end()) {
        std::fprintf(stderr, "%s: error: no object with \"shader\": \"diffraction\"\n", scenePath.c_str());
        return 2;
    }
    const DiffractionMaterial asWritten = *disc->diffraction;

    prism::scene::Scene phong = scene;
    auto& phongDisc = phong.objects[static_cast<std::size_t>(disc - scene.objects.begin())];
    phongDisc.shader = "phong";
    phongDisc.diffraction.reset();
    phongDisc.diffractionPointer.clear();

    const auto withSetting = [&](const Setting& s) {
        prism::scene::Scene out = scene;
        auto& m = *out.objects[static_cast<std::size_t>(disc - scene.objects.begin())].diffraction;
        m.path = s.path;
        m.tableSize = s.tableSize;
        m.wSlices = s.slices;
        m.wavelengthStepNm = s.stepNm;
        m.tolerance = s.tolerance;
        m.terms.reset();
        return out;
    };

    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    std::printf("prism_bench_diffraction_scene on %s (%s)\nscene %s at %dx%d, median of %d frames\n\n",
                context->info().renderer.c_str(), context->info().version.c_str(), scenePath.c_str(), size, size,
                frames);

    const Setting reference{"reference: a, 1024^2, 1 nm, tol 1e-6", 'a', 1024, 8, 1, 1e-6};
    const Image8 background = [&] {
        prism::scene::Scene empty = scene;
        empty.objects.clear();
        return renderer.render(empty);
    }();
    const Image8 referenceImage = renderer.render(withSetting(reference));

    std::vector<Setting> settings = {
        {std::string("as written (") + asWritten.path + ", " + std::to_string(asWritten.tableSize) + "^2, " +
             std::to_string(asWritten.wavelengthStepNm) + " nm)",
         asWritten.path, asWritten.tableSize, asWritten.wSlices, asWritten.wavelengthStepNm, asWritten.tolerance},
        {"c, 256^2, K 8, 5 nm", 'c', 256, 8, 5, 1e-6},
        {"c, 512^2, K 8, 5 nm (default)", 'c', 512, 8, 5, 1e-6},
        {"c, 1024^2, K 16, 5 nm", 'c', 1024, 16, 5, 1e-6},
        {"b, 512^2, 5 nm", 'b', 512, 8, 5, 1e-6},
        {"b, 512^2, 20 nm", 'b', 512, 8, 20, 1e-6},
    };
    std::printf(
        "| setting | ms | Phong ms | x Phong (target <= 4) | tables MiB | mean dE2000 (target <= 1) | p95 dE2000 | "
        "disc pixels |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Setting& s : settings) {
        const prism::scene::Scene sceneWith = withSetting(s);
        const Image8 image = renderer.render(sceneWith);  // warm-up: builds the tables once
        const double mib = static_cast<double>(renderer.lastFrame().diffractionTableBytes) / (1024.0 * 1024.0);
        renderer.render(phong);
        std::vector<double> ms, phongMs;
        for (int f = 0; f < frames; ++f) {
            ms.push_back(frameMs(renderer, sceneWith));
            phongMs.push_back(frameMs(renderer, phong));
        }
        const Error e = compare(referenceImage, image, background);
        const double ratio = median(ms) / median(phongMs);
        std::printf("| %s | %.2f | %.2f | %.2f %s | %.1f | %.3f %s | %.3f | %zu |\n", s.label.c_str(), median(ms),
                    median(phongMs), ratio, ratio <= 4.0 ? "(met)" : "(NOT met)", mib, e.mean,
                    e.mean <= 1.0 ? "(met)" : "(NOT met)", e.p95, e.pixels);
    }
    std::printf("\n%s; a frame is SceneRenderer::render (draw and read-back) of the whole scene.\n",
                reference.label.c_str());
    return 0;
}
