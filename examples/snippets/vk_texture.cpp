// The usage example of prism/vk/texture.hpp, compiled and run by tests/snippets.
#include <vector>

// [snippet]
#include "prism/vk/texture.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::vk::Device device;
    const std::vector<float> texels(4 * 4 * 4, 0.5f);  // 4x4 RGBA32F
    prism::vk::Texture lut(device, {.width = 4, .height = 4, .format = VK_FORMAT_R32G32B32A32_SFLOAT}, texels.data(),
                           texels.size() * sizeof(float));
    // sets.bindImage(resource, lut.view(), lut.sampler());  (prism/vk/pipeline.hpp)
    // [/snippet]
    return lut.view() != VK_NULL_HANDLE && lut.sampler() != VK_NULL_HANDLE ? 0 : 1;
}
