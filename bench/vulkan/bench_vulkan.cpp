// prism_bench_vulkan: the frame time of the classic catalogue through GL and through Vulkan,
// measured in one run of one program on this machine's drivers (llvmpipe and lavapipe on a
// machine without a GPU). A frame is one off-screen image as prism-render makes it: target,
// mesh upload, draw, read-back into a prism::image (renderImage8 and VulkanRenderer::render);
// programs and pipelines are built by a warm-up frame first and not timed.
//   prism_bench_vulkan [--size 512] [--runs 9]
// Prints a Markdown table: per gallery entry (shader and variant) the median over runs of
// the mean frame time over the four gallery meshes, for both APIs, and the median of each
// run's Vulkan / GL (the two alternate within a run, so load on the machine hits both).
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

// The mean milliseconds of one frame over `jobs`.
template <class Render>
double meanFrameMs(const std::vector<prism::render::RenderJob>& jobs, const Render& render) {
    const auto start = Clock::now();
    for (const auto& job : jobs) (void)render(job);
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count() / static_cast<double>(jobs.size());
}

struct Timing {
    double gl, vulkan, ratio;  // medians over the runs; ratio: of each run's Vulkan / GL
};

// GL and Vulkan alternate within each run, so a load change on the machine hits both.
template <class Gl, class Vk>
Timing timeBoth(const std::vector<prism::render::RenderJob>& jobs, int runs, const Gl& gl, const Vk& vk) {
    (void)meanFrameMs(jobs, gl);  // warm-up: programs and pipelines
    (void)meanFrameMs(jobs, vk);
    std::vector<double> g, v, r;
    for (int i = 0; i < runs; ++i) {
        g.push_back(meanFrameMs(jobs, gl));
        v.push_back(meanFrameMs(jobs, vk));
        r.push_back(v.back() / g.back());
    }
    return {median(g), median(v), median(r)};
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
    std::vector<double> glAll, vkAll, ratios;
    for (const auto& entry : prism::render::galleryEntries(prism::shaders::kCatalog)) {
        std::vector<prism::render::RenderJob> jobs;
        for (const auto& mesh : prism::render::kGalleryMeshes)
            jobs.push_back(prism::render::galleryJob(entry, mesh, size));
        const Timing t = timeBoth(
            jobs, runs, [&](const auto& job) { return prism::render::renderImage8(cache, job); },
            [&](const auto& job) { return vulkan.render(job); });
        glAll.push_back(t.gl);
        vkAll.push_back(t.vulkan);
        ratios.push_back(t.ratio);
        char row[160];
        std::snprintf(row, sizeof row, "| %s | %.2f | %.2f | %.2f |\n", entry.label.c_str(), t.gl, t.vulkan, t.ratio);
        std::cout << row;
    }
    char total[160];
    std::snprintf(total, sizeof total, "| **median of the entries** | %.2f | %.2f | %.2f |\n", median(glAll),
                  median(vkAll), median(ratios));
    std::cout << total;
    return 0;
}
