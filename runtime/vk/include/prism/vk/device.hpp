// A headless Vulkan 1.1 device for off-screen drawing: instance, an optional Khronos
// validation layer whose messages are counted, the physical device (a GPU first, else
// lavapipe, Mesa's Vulkan on the CPU), one graphics queue and a command pool.
//
// Usage (snippet: examples/snippets/vk_device.cpp):
//
//     #include "prism/vk/device.hpp"
//     prism::vk::Device device({.validation = true});                // VK_LAYER_KHRONOS_validation
//     std::string name = device.name();                              // "llvmpipe (LLVM 15.0.6, 256 bits)"
//     device.submit([](VkCommandBuffer) { /* record commands */ });  // runs them and waits
//     std::size_t messages = device.validationMessages().size();     // 0 when all is well
//
// No Vulkan driver (or no device with a graphics queue, VK_EXT_depth_clip_control and
// VK_EXT_provoking_vertex, see prism/vk/clip_convention.hpp) throws NoDeviceError saying
// what to install; asking for
// validation without the layer installed throws VkError naming its package.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "prism/vk/handles.hpp"

namespace prism::vk {

// No usable Vulkan device on this machine.
class NoDeviceError : public VkError {
  public:
    using VkError::VkError;
};

struct DeviceOptions {
    // Enable VK_LAYER_KHRONOS_validation with a debug-utils messenger that records every
    // warning and error it reports (validationMessages()).
    bool validation = false;
};

class Device {
  public:
    explicit Device(DeviceOptions options = {});
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkInstance instance() const { return instance_.get(); }
    VkPhysicalDevice physicalDevice() const { return physical_; }
    VkDevice device() const { return device_.get(); }
    VkQueue queue() const { return queue_; }
    const std::string& name() const { return name_; }
    bool validating() const { return options_.validation; }

    // The validation layer's warnings and errors since creation, "severity: message" each.
    std::vector<std::string> validationMessages() const;

    // The index of a memory type allowed by `typeBits` with all of `properties`; throws VkError.
    std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags properties) const;

    // Records `commands` into a fresh primary command buffer, submits it and waits for it.
    void submit(const std::function<void(VkCommandBuffer)>& commands) const;

    // Recorded by the messenger; shared with its callback, so it has a fixed address.
    struct MessageLog {
        mutable std::mutex mutex;
        std::vector<std::string> messages;
    };

  private:
    DeviceOptions options_;
    std::unique_ptr<MessageLog> log_;
    Instance instance_;
    DebugMessenger messenger_;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    std::string name_;
    std::uint32_t queueFamily_ = 0;
    LogicalDevice device_;
    VkQueue queue_ = VK_NULL_HANDLE;
    CommandPool commandPool_;
};

}  // namespace prism::vk
