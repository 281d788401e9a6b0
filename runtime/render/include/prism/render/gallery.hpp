// The gallery's images, the main job's grid: every catalogue shader with the variant its
// lights need, then each of its boolean axes switched on (phong BLINN=1, every FOG=1), on
// the gallery meshes, framed so that three faces of the cube and the torus's hole show.
// prism-gallery renders them through GL; the Vulkan tier and bench draw the same jobs
// through Vulkan to compare the APIs (docs/vulkan.md).
//
// Usage (snippet: examples/snippets/render_gallery.cpp):
//
//     #include "prism/render/gallery.hpp"
//     #include "prism/shaders.hpp"
//     for (const auto& entry : prism::render::galleryEntries(prism::shaders::kCatalog))
//         for (const auto& mesh : prism::render::kGalleryMeshes) {
//             prism::render::RenderJob job = prism::render::galleryJob(entry, mesh, 128);
//             // renderImage8(cache, job) or VulkanRenderer::render(job)
//     }
#pragma once

#include <array>
#include <string>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/render/offscreen_render.hpp"

namespace prism::render {

struct GalleryEntry {
    std::string shader;
    VariantValues variant;
    std::string fileStem;  // "phong" or "phong.BLINN-1"
    std::string label;     // "phong" or "phong BLINN=1"
};

inline const std::array<std::string, 4> kGalleryMeshes = {"sphere", "torus", "cube", "trefoil"};

// One entry per shader with the variant its lights need (derived by the renderer), then
// one per other boolean axis switched on.
std::vector<GalleryEntry> galleryEntries(const catalog::Catalog& catalog);

// The entry's shader and variant on `mesh` (a namedMesh name, subdivision 3), `size` pixels
// square, turned 20 degrees about x and -30 about y; FOG=1 entries get the default fog.
RenderJob galleryJob(const GalleryEntry& entry, const std::string& mesh, int size);

}  // namespace prism::render
