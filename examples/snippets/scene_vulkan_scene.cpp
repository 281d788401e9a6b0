// The usage example of prism/scene/vulkan_scene.hpp, compiled and run by tests/snippets
// (in a directory where examples/scenes is linked).
// [snippet]
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/vulkan_scene.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto scene = prism::scene::loadScene("examples/scenes/four_lights.json");
    prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
    prism::image::Image8 image = vulkan.render(prism::scene::vulkanFrameOf(scene));
    // [/snippet]
    return image.width == scene.width && vulkan.pipelineCount() == 2 ? 0 : 1;
}
