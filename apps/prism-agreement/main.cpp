// prism-agreement: the main job's "Vulkan and GL agree" section. Renders every gallery job
// (prism/render/gallery.hpp: each classic shader and boolean variant on the four gallery
// meshes) through GL and through Vulkan from the catalogue's SPIR-V, and writes
//   DIR/agreement.tsv       shader, variant, mesh, max, within2, mean: one row per job (the
//                           largest channel difference, the share of pixels within 2/255, the
//                           mean absolute error in 8-bit units)
//   DIR/agreement-pair.png  GL | Vulkan | difference x8, of the job that differs most
// and prints one "[k/N] label max M" line per job. Usage errors exit 2.
//   prism-agreement --out gallery/vulkan [--size 256]
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "prism/gl/gl_context.hpp"
#include "prism/image/contact_sheet.hpp"
#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/gallery.hpp"
#include "prism/render/vulkan_render.hpp"
#include "prism/shaders.hpp"

namespace {

struct Worst {
    int max = -1;
    std::string label;
    prism::image::Image8 gl, vulkan, diff;
};

// Renders and compares every job, writing the TSV; returns the job that differs most.
Worst compareAll(const std::filesystem::path& out, int size) {
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
    std::ofstream tsv(out / "agreement.tsv");
    tsv << "shader\tvariant\tmesh\tmax\twithin2\tmean\n";
    const auto entries = prism::render::galleryEntries(prism::shaders::kCatalog);
    const std::size_t total = entries.size() * prism::render::kGalleryMeshes.size();
    Worst worst;
    std::size_t k = 0;
    for (const auto& entry : entries)
        for (const auto& mesh : prism::render::kGalleryMeshes) {
            const auto job = prism::render::galleryJob(entry, mesh, size);
            auto gl = prism::render::renderImage8(cache, job);
            auto vk = vulkan.render(job);
            const auto cmp = prism::image::compareImages(vk, gl, 2);
            const std::string variant =
                entry.label.size() > entry.shader.size() ? entry.label.substr(entry.shader.size() + 1) : "";
            tsv << entry.shader << '\t' << variant << '\t' << mesh << '\t' << cmp.maxChannelDiff << '\t'
                << 1.0 - cmp.shareOver << '\t' << cmp.meanAbsError << '\n';
            std::cout << "[" << ++k << "/" << total << "] " << entry.label << " / " << mesh << " max "
                      << cmp.maxChannelDiff << std::endl;
            if (cmp.maxChannelDiff > worst.max)
                worst = {cmp.maxChannelDiff, entry.label + " / " + mesh, std::move(gl), std::move(vk), cmp.diff};
        }
    if (!tsv.flush()) throw std::runtime_error("cannot write " + (out / "agreement.tsv").string());
    std::cout << "vulkan: " << vulkan.device().name() << "\n";
    return worst;
}

}  // namespace

int main(int argc, char** argv) {
    std::string outDir = "agreement";
    int size = 256;
    CLI::App app{"prism-agreement: every gallery job through GL and Vulkan, compared pixel by pixel"};
    app.add_option("--out", outDir, "output directory")->capture_default_str();
    app.add_option("--size", size, "image width and height")->capture_default_str()->check(CLI::Range(16, 2048));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        auto context = prism::gl::createContext();
        std::filesystem::create_directories(outDir);
        const Worst worst = compareAll(outDir, size);
        const std::vector<prism::image::Image8> pair{worst.gl, worst.vulkan, worst.diff};
        const std::vector<std::string> labels{"GL", "Vulkan", "diff x8"};
        prism::image::writePng(std::filesystem::path(outDir) / "agreement-pair.png",
                               prism::image::composeContactSheet(pair, labels, 3));
        std::cout << "largest difference: " << worst.label << ", " << worst.max << "/255\n";
    } catch (const std::exception& e) {
        std::cerr << "prism-agreement: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
