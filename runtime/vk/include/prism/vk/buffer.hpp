// Device memory and host-visible buffers: vertex, index, uniform and read-back storage,
// mapped for their whole life so the CPU writes them in place.
//
// Usage (snippet: examples/snippets/vk_buffer.cpp):
//
//     #include "prism/vk/buffer.hpp"
//     prism::vk::Device device;
//     const float corners[] = {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f};
//     prism::vk::Buffer vertices(device, sizeof corners, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
//     vertices.write(corners, sizeof corners);  // at offset 0; visible to the device at once
//     VkBuffer raw = vertices.get();            // for vkCmdBindVertexBuffers
//
// Buffers live in HOST_VISIBLE | HOST_COHERENT memory: Prism's draws are small and
// read back, so a staging copy would cost more than it saves. Move-only.
#pragma once

#include <cstddef>

#include "prism/vk/device.hpp"
#include "prism/vk/handles.hpp"

namespace prism::vk {

// Memory for `requirements` with `properties` (vkAllocateMemory); throws VkError.
Memory allocateMemory(const Device& device, const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties);
// The image `info` describes, bound to DEVICE_LOCAL `memory` allocated for it; throws VkError.
ImageObject createDeviceImage(const Device& device, const VkImageCreateInfo& info, Memory& memory);

class Buffer {
  public:
    Buffer() = default;
    Buffer(const Device& device, VkDeviceSize bytes, VkBufferUsageFlags usage);

    VkBuffer get() const { return buffer_.get(); }
    VkDeviceSize bytes() const { return bytes_; }
    // Copies `bytes` bytes from `data` to `offset`; throws std::out_of_range past the end.
    void write(const void* data, std::size_t bytes, std::size_t offset = 0);
    const std::byte* data() const { return static_cast<const std::byte*>(mapped_); }

  private:
    Memory memory_;  // declared first: destroyed after the buffer bound to it
    BufferObject buffer_;
    void* mapped_ = nullptr;
    VkDeviceSize bytes_ = 0;
};

}  // namespace prism::vk
