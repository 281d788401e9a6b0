// The usage example of prism/vk/clip_convention.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/vk/clip_convention.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::vk::ClipConvention gl;                      // GL's conventions (the default)
    VkViewport viewport = gl.viewport(160, 120);       // y = 120, height = -120
    prism::vk::ClipConvention broken{.flipY = false};  // a fault for the tests that must catch it
    // [/snippet]
    return viewport.y == 120.0f && viewport.height == -120.0f && broken.viewport(160, 120).height > 0 ? 0 : 1;
}
