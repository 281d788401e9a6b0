// Destruction and counting of Vulkan objects, and VkResult names (see prism/vk/handles.hpp).
#include "prism/vk/handles.hpp"

namespace prism::vk {
namespace {

counters::ObjectCounters<ObjectKind> g_counters;

void gone(ObjectKind kind) {
    g_counters.destroyed(kind);
}

}  // namespace

std::string resultName(VkResult result) {
    switch (result) {
#define PRISM_VK_RESULT(name) \
    case name: return #name
        PRISM_VK_RESULT(VK_SUCCESS);
        PRISM_VK_RESULT(VK_NOT_READY);
        PRISM_VK_RESULT(VK_TIMEOUT);
        PRISM_VK_RESULT(VK_INCOMPLETE);
        PRISM_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY);
        PRISM_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY);
        PRISM_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED);
        PRISM_VK_RESULT(VK_ERROR_DEVICE_LOST);
        PRISM_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED);
        PRISM_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT);
        PRISM_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT);
        PRISM_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT);
        PRISM_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER);
        PRISM_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS);
        PRISM_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED);
#undef PRISM_VK_RESULT
        default: return "VkResult " + std::to_string(static_cast<int>(result));
    }
}

void check(VkResult result, const std::string& what) {
    if (result != VK_SUCCESS) throw VkError(what + " failed: " + resultName(result));
}

ObjectCounts objectCounts() {
    return g_counters.counts();
}

void detail::counted(ObjectKind kind) {
    g_counters.created(kind);
}

void detail::destroy(VkInstance, VkInstance object) noexcept {
    vkDestroyInstance(object, nullptr);
    gone(ObjectKind::Instance);
}

void detail::destroy(VkInstance parent, VkDebugUtilsMessengerEXT object) noexcept {
    auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(parent, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroyMessenger) destroyMessenger(parent, object, nullptr);
    gone(ObjectKind::DebugMessenger);
}

void detail::destroy(VkInstance, VkDevice object) noexcept {
    vkDestroyDevice(object, nullptr);
    gone(ObjectKind::Device);
}

// The device's children: vkDestroy<Type>(device, object, nullptr), then the count.
#define PRISM_VK_DEVICE_CHILD(Type, Destroy, Kind)                \
    void detail::destroy(VkDevice parent, Type object) noexcept { \
        Destroy(parent, object, nullptr);                         \
        gone(ObjectKind::Kind);                                   \
    }
PRISM_VK_DEVICE_CHILD(VkDeviceMemory, vkFreeMemory, Memory)
PRISM_VK_DEVICE_CHILD(VkBuffer, vkDestroyBuffer, Buffer)
PRISM_VK_DEVICE_CHILD(VkImage, vkDestroyImage, Image)
PRISM_VK_DEVICE_CHILD(VkImageView, vkDestroyImageView, ImageView)
PRISM_VK_DEVICE_CHILD(VkSampler, vkDestroySampler, Sampler)
PRISM_VK_DEVICE_CHILD(VkShaderModule, vkDestroyShaderModule, ShaderModule)
PRISM_VK_DEVICE_CHILD(VkDescriptorSetLayout, vkDestroyDescriptorSetLayout, DescriptorSetLayout)
PRISM_VK_DEVICE_CHILD(VkDescriptorPool, vkDestroyDescriptorPool, DescriptorPool)
PRISM_VK_DEVICE_CHILD(VkPipelineLayout, vkDestroyPipelineLayout, PipelineLayout)
PRISM_VK_DEVICE_CHILD(VkPipeline, vkDestroyPipeline, Pipeline)
PRISM_VK_DEVICE_CHILD(VkRenderPass, vkDestroyRenderPass, RenderPass)
PRISM_VK_DEVICE_CHILD(VkFramebuffer, vkDestroyFramebuffer, Framebuffer)
PRISM_VK_DEVICE_CHILD(VkCommandPool, vkDestroyCommandPool, CommandPool)
PRISM_VK_DEVICE_CHILD(VkFence, vkDestroyFence, Fence)
#undef PRISM_VK_DEVICE_CHILD

}  // namespace prism::vk
