// Move-only owners of Vulkan objects, one template for every object kind, and process-wide
// counters of the objects created and alive (for leak checks), as prism/gl/handles.hpp is for
// GL. Every Vulkan object prism::vk makes is owned through these.
//
// Usage (snippet: examples/snippets/vk_handles.cpp):
//
//     #include "prism/vk/device.hpp"
//     #include "prism/vk/handles.hpp"
//     prism::vk::Device device;  // lavapipe or a GPU (prism/vk/device.hpp)
//     VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
//     VkSampler raw = VK_NULL_HANDLE;
//     prism::vk::check(vkCreateSampler(device.device(), &info, nullptr, &raw), "vkCreateSampler");
//     prism::vk::Sampler sampler(device.device(), raw);                            // owns it from here
//     auto live = prism::vk::objectCounts().live(prism::vk::ObjectKind::Sampler);  // >= 1
//     // leaving the scope destroys the sampler (vkDestroySampler), then the device
//
// A default-constructed handle owns nothing (get() == VK_NULL_HANDLE). A handle's parent
// (the VkDevice, or the VkInstance for a debug messenger) must outlive it.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "prism/counters/object_counters.hpp"

namespace prism::vk {

// Every failure of prism::vk: the call, its VkResult, and what to do.
class VkError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Throws VkError "<what> failed: VK_ERROR_..." unless `result` is VK_SUCCESS.
void check(VkResult result, const std::string& what);
// VkResult's enumerator name ("VK_ERROR_OUT_OF_DEVICE_MEMORY").
std::string resultName(VkResult result);

enum class ObjectKind : int {
    Instance,
    DebugMessenger,
    Device,
    Memory,
    Buffer,
    Image,
    ImageView,
    Sampler,
    ShaderModule,
    DescriptorSetLayout,
    DescriptorPool,
    PipelineLayout,
    Pipeline,
    RenderPass,
    Framebuffer,
    CommandPool,
    Fence,
    Count
};

// Objects created since start-up and alive now, per kind (prism/counters/object_counters.hpp).
using ObjectCounts = counters::Counts<ObjectKind>;
ObjectCounts objectCounts();

namespace detail {
void counted(ObjectKind kind);  // one more created and alive
// Destroys `object` with its parent and counts it gone; one overload per Vulkan type.
void destroy(VkInstance parent, VkInstance object) noexcept;
void destroy(VkInstance parent, VkDebugUtilsMessengerEXT object) noexcept;
void destroy(VkInstance parent, VkDevice object) noexcept;
void destroy(VkDevice parent, VkDeviceMemory object) noexcept;
void destroy(VkDevice parent, VkBuffer object) noexcept;
void destroy(VkDevice parent, VkImage object) noexcept;
void destroy(VkDevice parent, VkImageView object) noexcept;
void destroy(VkDevice parent, VkSampler object) noexcept;
void destroy(VkDevice parent, VkShaderModule object) noexcept;
void destroy(VkDevice parent, VkDescriptorSetLayout object) noexcept;
void destroy(VkDevice parent, VkDescriptorPool object) noexcept;
void destroy(VkDevice parent, VkPipelineLayout object) noexcept;
void destroy(VkDevice parent, VkPipeline object) noexcept;
void destroy(VkDevice parent, VkRenderPass object) noexcept;
void destroy(VkDevice parent, VkFramebuffer object) noexcept;
void destroy(VkDevice parent, VkCommandPool object) noexcept;
void destroy(VkDevice parent, VkFence object) noexcept;
}  // namespace detail

// Owns `object`, made by the caller's vkCreate* with `parent`; counted as `Kind`.
template <class Parent, class T, ObjectKind Kind>
class Handle {
  public:
    Handle() = default;
    Handle(Parent parent, T object) : parent_(parent), object_(object) {
        if (object_ != VK_NULL_HANDLE) detail::counted(Kind);
    }
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept
        : parent_(std::exchange(other.parent_, VK_NULL_HANDLE)),
          object_(std::exchange(other.object_, VK_NULL_HANDLE)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            parent_ = std::exchange(other.parent_, VK_NULL_HANDLE);
            object_ = std::exchange(other.object_, VK_NULL_HANDLE);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    T get() const { return object_; }
    explicit operator bool() const { return object_ != VK_NULL_HANDLE; }
    // Destroys the object now (a no-op for an empty handle).
    void reset() noexcept {
        if (object_ != VK_NULL_HANDLE) detail::destroy(parent_, std::exchange(object_, VK_NULL_HANDLE));
    }

  private:
    Parent parent_ = VK_NULL_HANDLE;
    T object_ = VK_NULL_HANDLE;
};

using Instance = Handle<VkInstance, VkInstance, ObjectKind::Instance>;  // parent: VK_NULL_HANDLE
using DebugMessenger = Handle<VkInstance, VkDebugUtilsMessengerEXT, ObjectKind::DebugMessenger>;
using LogicalDevice = Handle<VkInstance, VkDevice, ObjectKind::Device>;
using Memory = Handle<VkDevice, VkDeviceMemory, ObjectKind::Memory>;
using BufferObject = Handle<VkDevice, VkBuffer, ObjectKind::Buffer>;
using ImageObject = Handle<VkDevice, VkImage, ObjectKind::Image>;
using ImageView = Handle<VkDevice, VkImageView, ObjectKind::ImageView>;
using Sampler = Handle<VkDevice, VkSampler, ObjectKind::Sampler>;
using ShaderModule = Handle<VkDevice, VkShaderModule, ObjectKind::ShaderModule>;
using DescriptorSetLayout = Handle<VkDevice, VkDescriptorSetLayout, ObjectKind::DescriptorSetLayout>;
using DescriptorPool = Handle<VkDevice, VkDescriptorPool, ObjectKind::DescriptorPool>;
using PipelineLayout = Handle<VkDevice, VkPipelineLayout, ObjectKind::PipelineLayout>;
using PipelineObject = Handle<VkDevice, VkPipeline, ObjectKind::Pipeline>;
using RenderPass = Handle<VkDevice, VkRenderPass, ObjectKind::RenderPass>;
using FramebufferObject = Handle<VkDevice, VkFramebuffer, ObjectKind::Framebuffer>;
using CommandPool = Handle<VkDevice, VkCommandPool, ObjectKind::CommandPool>;
using Fence = Handle<VkDevice, VkFence, ObjectKind::Fence>;

}  // namespace prism::vk
