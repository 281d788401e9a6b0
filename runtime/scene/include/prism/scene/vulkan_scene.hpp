// A JSON scene as a Vulkan frame (prism/render/vulkan_render.hpp): its camera, lights, fog
// and objects drawn with the catalogue's classic shaders from their SPIR-V, exactly as
// SceneRenderer draws them through GL (the fog colour as background, the same variants).
// A diffraction object is drawn with the diffraction catalogue's SPIR-V and its material's
// lookup tables, built on the CPU as for GL (prism/scene/diffraction_object.hpp) and
// uploaded as Vulkan images (prism/diffraction/diffraction_vk.hpp).
//
// Usage (snippet: examples/snippets/scene_vulkan_scene.cpp):
//
//     #include "prism/scene/scene_loader.hpp"
//     #include "prism/scene/vulkan_scene.hpp"
//     #include "prism/shaders.hpp"
//     auto scene = prism::scene::loadScene("examples/scenes/four_lights.json");
//     prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
//     prism::image::Image8 image = vulkan.render(prism::scene::vulkanFrameOf(scene));
//
// A scene with a system that has no Vulkan path (rain, water, fog billboards) throws
// SceneError naming the system and its JSON key: never a silently incomplete picture. A
// diffraction material that cannot be built throws SceneError naming its JSON pointer, as
// SceneRenderer does. A "stochastic" scene is no frame of draws: renderStochasticVulkan draws it.
#pragma once

#include "prism/render/vulkan_render.hpp"
#include "prism/scene/scene.hpp"

namespace prism::scene {

render::VulkanFrame vulkanFrameOf(const Scene& scene);

// A "stochastic" scene's soft shadows through Vulkan (prism/bluenoise/vk_soft_shadows.hpp):
// the tables, options and frame loop of renderStochastic (prism/scene/stochastic.hpp), each
// frame drawn from the blue-noise catalogue's SPIR-V, as a grey image. Throws
// std::invalid_argument for settings renderStochastic refuses. `clip` is GL's row order; the
// agreement tests pass another to show it matters.
image::Image8 renderStochasticVulkan(const StochasticSettings& settings, int width, int height,
                                     const vk::Device& device, vk::ClipConvention clip = {.glRowOrder = true});

}  // namespace prism::scene
