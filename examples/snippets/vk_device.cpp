// The usage example of prism/vk/device.hpp, compiled and run by tests/snippets.
#include <cstddef>
#include <string>

// [snippet]
#include "prism/vk/device.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::vk::Device device({.validation = true});                // VK_LAYER_KHRONOS_validation
    std::string name = device.name();                              // "llvmpipe (LLVM 15.0.6, 256 bits)"
    device.submit([](VkCommandBuffer) { /* record commands */ });  // runs them and waits
    std::size_t messages = device.validationMessages().size();     // 0 when all is well
    // [/snippet]
    return !name.empty() && messages == 0 ? 0 : 1;
}
