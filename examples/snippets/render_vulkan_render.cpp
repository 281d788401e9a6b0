// The usage example of prism/render/vulkan_render.hpp, compiled and run by tests/snippets.
#include <cstddef>

// [snippet]
#include "prism/render/shader_meshes.hpp"
#include "prism/render/vulkan_render.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog, {.device = {.validation = true}});
    prism::render::RenderJob job;  // as for renderImage8: shader, variant, mesh, lights, size
    job.shader = "phong";
    job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
    prism::image::Image8 image = vulkan.render(job);
    std::size_t messages = vulkan.device().validationMessages().size();  // 0
    // [/snippet]
    return messages == 0 && image.at(256, 256) != image.at(0, 0) ? 0 : 1;
}
