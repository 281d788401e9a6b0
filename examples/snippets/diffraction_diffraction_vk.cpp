// The usage example of prism/diffraction/diffraction_vk.hpp, compiled and run by tests/snippets
// (lavapipe, no GL).
#include <memory>
#include <utility>

#include "prism/shaders.hpp"
// [snippet]
#include "prism/diffraction/diffraction_vk.hpp"
#include "prism/diffraction_shaders.hpp"
#include "prism/render/shader_meshes.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
    MaterialTables tables;
    tables.integrated = buildIntegratedTables(buildSpectralTables(brdf, {.size = 32}));  // path (b)
    prism::render::VulkanDraw draw;
    draw.shader = "diffraction";
    draw.catalog = &prism::diffraction_shaders::kCatalog;
    draw.extras = std::make_shared<VulkanDiffractionTables>(std::move(tables));
    draw.variant = {{"DIFFRACTION_PATH", "1"}};
    draw.mesh = prism::render::meshForShader("diffraction", prism::render::namedMesh("grid", 2));
    prism::render::VulkanFrame frame;
    frame.draws.push_back(std::move(draw));
    prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
    prism::image::Image8 image = vulkan.render(frame);
    // [/snippet]
    return image.width == 512 && vulkan.pipelineCount() == 1 ? 0 : 1;
}
