// prism_bench_vulkan: the frame time of the classic catalogue through GL and through Vulkan,
// measured in one run of one program on this machine's drivers (llvmpipe and lavapipe on a
// machine without a GPU). A frame is one off-screen image as prism-render makes it: target,
// mesh upload, draw, read-back into a prism::image (renderImage8 and VulkanRenderer::render);
// programs and pipelines are built by a warm-up frame first and not timed.
//   prism_bench_vulkan [--size 512] [--runs 9]
// Prints a Markdown table: per gallery entry (shader and variant) the median over runs of
// the mean frame time over the four gallery meshes, for both APIs, and Vulkan / GL.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

#include "prism/gl/gl_context.hpp"
#include "prism/render/gallery.hpp"
#include "prism/render/vulkan_render.hpp"
#include "prism/shaders.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// The mean milliseconds of one frame of each job, `runs` times; the median of those means.
template <class Render>
double medianFrameMs(const std::vector<prism::render::RenderJob>& jobs, int runs, const Render& render) {
    for (const auto& job : jobs) (void)render(job);  // warm-up: programs and pipelines
    std::vector<double> means;
    for (int r = 0; r < runs; ++r) {
        const auto start = Clock::now();
        for (const auto& job : jobs) (void)render(job);
        means.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count() /
                        static_cast<double>(jobs.size()));
    }
    return median(means);
}

}  // namespace

int main(int argc, char** argv) {
    int size = 512, runs = 9;
    CLI::App app{"prism_bench_vulkan: GL vs Vulkan frame time for the classic catalogue"};
    app.add_option("--size", size, "image width and height")->capture_default_str()->check(CLI::Range(16, 4096));
    app.add_option("--runs", runs, "timed runs per entry (the median is printed)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    CLI11_PARSE(app, argc, argv);

    auto context = prism::gl::createContext();
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
    std::cout << "GL: " << context->info().renderer << " | Vulkan: " << vulkan.device().name() << " | " << size << "x"
              << size << ", median of " << runs << " runs of the 4 gallery meshes\n\n";
    std::cout << "| shader | GL ms/frame | Vulkan ms/frame | Vulkan / GL |\n|---|---|---|---|\n";
    std::vector<double> glAll, vkAll;
    for (const auto& entry : prism::render::galleryEntries(prism::shaders::kCatalog)) {
        std::vector<prism::render::RenderJob> jobs;
        for (const auto& mesh : prism::render::kGalleryMeshes)
            jobs.push_back(prism::render::galleryJob(entry, mesh, size));
        const double gl =
            medianFrameMs(jobs, runs, [&](const auto& job) { return prism::render::renderImage8(cache, job); });
        const double vk = medianFrameMs(jobs, runs, [&](const auto& job) { return vulkan.render(job); });
        glAll.push_back(gl);
        vkAll.push_back(vk);
        char row[160];
        std::snprintf(row, sizeof row, "| %s | %.2f | %.2f | %.2f |\n", entry.label.c_str(), gl, vk, vk / gl);
        std::cout << row;
    }
    char total[160];
    std::snprintf(total, sizeof total, "| **median of the entries** | %.2f | %.2f | %.2f |\n", median(glAll),
                  median(vkAll), median(vkAll) / median(glAll));
    std::cout << total;
    return 0;
}
