// Sampled images filled through a staging buffer (see prism/vk/texture.hpp).
#include "prism/vk/texture.hpp"

#include <stdexcept>
#include <string>

#include "prism/vk/buffer.hpp"

namespace prism::vk {
namespace {

ImageObject createImage(const Device& device, const TextureDescription& d, Memory& memory) {
    const bool volume = d.type == VK_IMAGE_VIEW_TYPE_3D;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = volume ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = d.format;
    info.extent = {static_cast<std::uint32_t>(d.width), static_cast<std::uint32_t>(d.height),
                   volume ? static_cast<std::uint32_t>(d.depth) : 1u};
    info.mipLevels = 1;
    info.arrayLayers = volume ? 1u : static_cast<std::uint32_t>(d.depth);
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return createDeviceImage(device, info, memory);
}

void transition(VkCommandBuffer cmd, VkImage image, std::uint32_t layers, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = from == VK_IMAGE_LAYOUT_UNDEFINED ? 0 : VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask =
        from == VK_IMAGE_LAYOUT_UNDEFINED ? VK_ACCESS_TRANSFER_WRITE_BIT : VK_ACCESS_SHADER_READ_BIT;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    const VkPipelineStageFlags src =
        from == VK_IMAGE_LAYOUT_UNDEFINED ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT;
    const VkPipelineStageFlags dst = from == VK_IMAGE_LAYOUT_UNDEFINED
                                         ? VK_PIPELINE_STAGE_TRANSFER_BIT
                                         : VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

ImageView createView(const Device& device, VkImage image, const TextureDescription& d) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = d.type;
    info.format = d.format;
    const std::uint32_t layers = d.type == VK_IMAGE_VIEW_TYPE_3D ? 1u : static_cast<std::uint32_t>(d.depth);
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device.device(), &info, nullptr, &view), "vkCreateImageView of a texture");
    return ImageView(device.device(), view);
}

Sampler createSampler(const Device& device, VkFilter filter) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    check(vkCreateSampler(device.device(), &info, nullptr, &sampler), "vkCreateSampler");
    return Sampler(device.device(), sampler);
}

void requireValid(const TextureDescription& d, std::size_t bytes) {
    if (d.width < 1 || d.height < 1 || d.depth < 1)
        throw std::invalid_argument("prism::vk::Texture: size " + std::to_string(d.width) + "x" +
                                    std::to_string(d.height) + "x" + std::to_string(d.depth) + " is empty");
    if (d.type != VK_IMAGE_VIEW_TYPE_2D && d.type != VK_IMAGE_VIEW_TYPE_2D_ARRAY && d.type != VK_IMAGE_VIEW_TYPE_3D)
        throw std::invalid_argument("prism::vk::Texture: the view type must be 2D, 2D_ARRAY or 3D");
    if (d.type == VK_IMAGE_VIEW_TYPE_2D && d.depth != 1)
        throw std::invalid_argument("prism::vk::Texture: a 2D texture has depth 1");
    const std::size_t expected = static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height) *
                                 static_cast<std::size_t>(d.depth) * texelBytes(d.format);
    if (bytes != expected)
        throw std::invalid_argument("prism::vk::Texture: " + std::to_string(bytes) +
                                    " bytes of texels for an image of " + std::to_string(expected));
}

}  // namespace

std::size_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        case VK_FORMAT_R32G32_SFLOAT: return 8;
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R8G8B8A8_UNORM: return 4;
        default: break;
    }
    throw std::invalid_argument("prism::vk::Texture: format " + std::to_string(static_cast<int>(format)) +
                                " is not one it uploads (RGBA32F, RG32F, R32F, R32UI, RGBA8)");
}

Texture::Texture(const Device& device, const TextureDescription& description, const void* texels, std::size_t bytes)
    : description_(description) {
    requireValid(description, bytes);
    image_ = createImage(device, description, memory_);
    Buffer staging(device, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    staging.write(texels, bytes);
    const bool volume = description.type == VK_IMAGE_VIEW_TYPE_3D;
    const auto layers = volume ? 1u : static_cast<std::uint32_t>(description.depth);
    device.submit([&](VkCommandBuffer cmd) {
        transition(cmd, image_.get(), layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
        region.imageExtent = {static_cast<std::uint32_t>(description.width),
                              static_cast<std::uint32_t>(description.height),
                              volume ? static_cast<std::uint32_t>(description.depth) : 1u};
        vkCmdCopyBufferToImage(cmd, staging.get(), image_.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(cmd, image_.get(), layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    });
    view_ = createView(device, image_.get(), description);
    sampler_ = createSampler(device, description.filter);
}

}  // namespace prism::vk
