// The usage example of prism/vk/buffer.hpp, compiled and run by tests/snippets.
#include <cstring>

// [snippet]
#include "prism/vk/buffer.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::vk::Device device;
    const float corners[] = {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f};
    prism::vk::Buffer vertices(device, sizeof corners, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    vertices.write(corners, sizeof corners);  // at offset 0; visible to the device at once
    VkBuffer raw = vertices.get();            // for vkCmdBindVertexBuffers
    // [/snippet]
    return raw != VK_NULL_HANDLE && std::memcmp(vertices.data(), corners, sizeof corners) == 0 ? 0 : 1;
}
