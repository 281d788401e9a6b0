// The usage example of prism/vk/render_target.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/vk/render_target.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::vk::Device device;
    prism::vk::RenderTarget target(device, 160, 120);
    device.submit([&](VkCommandBuffer cmd) {
        target.begin(cmd, {0.05f, 0.06f, 0.08f, 1.0f});  // clears colour and depth (1.0)
        // bind a pipeline and draw (prism/vk/pipeline.hpp)
        target.end(cmd);
    });
    prism::image::Image8 image = target.readImage8();  // row 0 at the top, like GL's after its flip
    // [/snippet]
    const prism::image::Rgba8 clear{13, 15, 20, 255};  // 0.05, 0.06, 0.08 as bytes
    return image.width == 160 && image.at(159, 119) == clear ? 0 : 1;
}
