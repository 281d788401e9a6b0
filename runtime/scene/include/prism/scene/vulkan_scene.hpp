// A JSON scene as a Vulkan frame (prism/render/vulkan_render.hpp): its camera, lights, fog
// and objects drawn with the catalogue's classic shaders from their SPIR-V, exactly as
// SceneRenderer draws them through GL (the fog colour as background, the same variants).
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
// A scene with a system that has no Vulkan path (rain, water, fog billboards, diffraction
// materials, the stochastic soft shadows) throws SceneError naming the system and its JSON
// key: never a silently incomplete picture.
#pragma once

#include "prism/render/vulkan_render.hpp"
#include "prism/scene/scene.hpp"

namespace prism::scene {

render::VulkanFrame vulkanFrameOf(const Scene& scene);

}  // namespace prism::scene
