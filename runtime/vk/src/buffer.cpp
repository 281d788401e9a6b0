// Host-visible buffers and memory allocation (see prism/vk/buffer.hpp).
#include "prism/vk/buffer.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

namespace prism::vk {

Memory allocateMemory(const Device& device, const VkMemoryRequirements& requirements,
                      VkMemoryPropertyFlags properties) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = device.memoryType(requirements.memoryTypeBits, properties);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device.device(), &info, nullptr, &memory),
          "vkAllocateMemory of " + std::to_string(requirements.size) + " bytes");
    return Memory(device.device(), memory);
}

ImageObject createDeviceImage(const Device& device, const VkImageCreateInfo& info, Memory& memory) {
    VkImage image = VK_NULL_HANDLE;
    check(vkCreateImage(device.device(), &info, nullptr, &image), "vkCreateImage");
    ImageObject owned(device.device(), image);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device.device(), image, &requirements);
    memory = allocateMemory(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(vkBindImageMemory(device.device(), image, memory.get(), 0), "vkBindImageMemory");
    return owned;
}

Buffer::Buffer(const Device& device, VkDeviceSize bytes, VkBufferUsageFlags usage) : bytes_(bytes) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = bytes == 0 ? 4 : bytes;  // Vulkan refuses empty buffers
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device.device(), &info, nullptr, &buffer), "vkCreateBuffer");
    BufferObject owned(device.device(), buffer);
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.device(), buffer, &requirements);
    memory_ = allocateMemory(device, requirements,
                             VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(device.device(), buffer, memory_.get(), 0), "vkBindBufferMemory");
    check(vkMapMemory(device.device(), memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    buffer_ = std::move(owned);
}

void Buffer::write(const void* data, std::size_t bytes, std::size_t offset) {
    if (offset + bytes > bytes_)
        throw std::out_of_range("prism::vk::Buffer: writing " + std::to_string(bytes) + " bytes at " +
                                std::to_string(offset) + " into a buffer of " + std::to_string(bytes_));
    std::memcpy(static_cast<std::byte*>(mapped_) + offset, data, bytes);
}

}  // namespace prism::vk
