// prism-gallery: the main job. Renders every catalogue shader (and its BLINN/FOG variants)
// on a sphere, a torus, a cube and a trefoil knot at 512x512, headlessly, and writes
// DIR/<shader>-<mesh>.png plus a labelled contact sheet DIR/gallery.png, and
// DIR/catalogue.tsv (file, shader, variant, mesh, seconds: one row per image, read by
// scripts/gallery_report.py) and DIR/live-views.json, what each image was drawn with, for the
// report's live WebGL2 views (live_views.hpp, docs/web.md). It prints "renderer: ..." and one
// "[k/N] label 0.12 s" line per image. Usage errors (unknown flags, a bad --backend) exit 2.
//   prism-gallery --out gallery [--size 512] [--backend egl|osmesa]
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "prism/image/contact_sheet.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/gallery.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"

#include "live_views.hpp"

int main(int argc, char** argv) {
    std::string outDir = "gallery", backendName;
    int size = 512;
    CLI::App app{"prism-gallery: render every catalogue shader on several meshes, headlessly"};
    app.add_option("--out", outDir, "output directory")->capture_default_str();
    app.add_option("--size", size, "image width and height")->capture_default_str()->check(CLI::Range(16, 4096));
    app.add_option("--backend", backendName, "egl|osmesa (default: egl, else osmesa)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    const auto backend = backendName.empty() ? std::nullopt : prism::gl::parseBackend(backendName);
    const bool glHeadless = backend && *backend != prism::gl::Backend::Glfw && *backend != prism::gl::Backend::Vulkan;
    if (!backendName.empty() && !glHeadless) {
        std::cerr << "prism-gallery: error: --backend " << backendName << ": expected egl or osmesa\n";
        return 2;
    }

    try {
        auto context = backend ? prism::gl::createContext(*backend) : prism::gl::createContext();
        std::cout << "renderer: " << context->info().renderer << " | " << context->info().version << "\n";
        std::filesystem::create_directories(outDir);
        prism::render::ProgramCache cache(prism::shaders::kCatalog);
        const auto& meshes = prism::render::kGalleryMeshes;
        const auto entries = prism::render::galleryEntries(prism::shaders::kCatalog);
        const std::size_t total = entries.size() * meshes.size();
        std::ofstream tsv(std::filesystem::path(outDir) / "catalogue.tsv");
        tsv << "file\tshader\tvariant\tmesh\tseconds\n";
        LiveViews live;
        std::vector<prism::image::Image8> shots;
        std::vector<std::string> labels;
        for (const auto& entry : entries) {
            for (const auto& meshName : meshes) {
                const auto start = std::chrono::steady_clock::now();
                const auto job = prism::render::galleryJob(entry, meshName, size);
                auto image = prism::render::renderImage8(cache, job);
                const auto path = std::filesystem::path(outDir) / (entry.fileStem + "-" + meshName + ".png");
                prism::image::writePng(path, image);
                const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                live.add(path.filename().string(), meshName, cache, job);  // not timed: the report's record
                const std::string variant =
                    entry.label.size() > entry.shader.size() ? entry.label.substr(entry.shader.size() + 1) : "";
                tsv << path.filename().string() << '\t' << entry.shader << '\t' << variant << '\t' << meshName << '\t'
                    << seconds << '\n';
                char line[64];
                std::snprintf(line, sizeof line, "%.2f s", seconds);
                std::cout << "[" << shots.size() + 1 << "/" << total << "] " << entry.label << " / " << meshName << " "
                          << line << std::endl;
                shots.push_back(std::move(image));
                labels.push_back(entry.label + "\n" + meshName);  // two lines: legible at 14 px in small cells
            }
        }
        if (!tsv.flush())
            throw std::runtime_error("cannot write " + (std::filesystem::path(outDir) / "catalogue.tsv").string());
        live.write(std::filesystem::path(outDir) / "live-views.json");
        prism::image::writePng(std::filesystem::path(outDir) / "gallery.png",
                               prism::image::composeContactSheet(shots, labels, static_cast<int>(meshes.size())));
        std::cout << "wrote " << (std::filesystem::path(outDir) / "gallery.png").string() << " (" << shots.size()
                  << " images, " << cache.size() << " programs)\n";
    } catch (const std::exception& e) {
        std::cerr << "prism-gallery: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
