// The usage example of prism/vk/handles.hpp, compiled and run by tests/snippets.
#include <cstdint>

// [snippet]
#include "prism/vk/device.hpp"
#include "prism/vk/handles.hpp"
// [/snippet]

// Returns how many samplers were alive inside; all objects are destroyed when it returns.
static std::uint64_t example() {
    // [snippet]
    prism::vk::Device device;  // lavapipe or a GPU (prism/vk/device.hpp)
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler raw = VK_NULL_HANDLE;
    prism::vk::check(vkCreateSampler(device.device(), &info, nullptr, &raw), "vkCreateSampler");
    prism::vk::Sampler sampler(device.device(), raw);                            // owns it from here
    auto live = prism::vk::objectCounts().live(prism::vk::ObjectKind::Sampler);  // >= 1
    // leaving the scope destroys the sampler (vkDestroySampler), then the device
    // [/snippet]
    return live;
}

int main() {
    const std::uint64_t inside = example();
    return inside == 1 && prism::vk::objectCounts().liveTotal() == 0 ? 0 : 1;
}
