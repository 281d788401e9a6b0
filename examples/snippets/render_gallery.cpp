// The usage example of prism/render/gallery.hpp, compiled and run by tests/snippets.
#include <cstddef>

// [snippet]
#include "prism/render/gallery.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    std::size_t jobs = 0;
    // [snippet]
    for (const auto& entry : prism::render::galleryEntries(prism::shaders::kCatalog))
        for (const auto& mesh : prism::render::kGalleryMeshes) {
            prism::render::RenderJob job = prism::render::galleryJob(entry, mesh, 128);
            // renderImage8(cache, job) or VulkanRenderer::render(job)
            // [/snippet]
            jobs += job.width == 128 && !job.mesh.indices.empty() ? 1 : 0;
            // [snippet]
        }
    // [/snippet]
    return jobs >= 40 ? 0 : 1;
}
