// A sampled image: a 2D, 2D-array or 3D image in device memory, filled once from the CPU
// through a staging buffer, with its view and its sampler (filter, clamp to edge), ready for
// DescriptorSets::bindImage at the set and binding the catalogue's reflection gives.
//
// Usage (snippet: examples/snippets/vk_texture.cpp):
//
//     #include "prism/vk/texture.hpp"
//     prism::vk::Device device;
//     const std::vector<float> texels(4 * 4 * 4, 0.5f);  // 4x4 RGBA32F
//     prism::vk::Texture lut(device, {.width = 4, .height = 4, .format = VK_FORMAT_R32G32B32A32_SFLOAT}, texels.data(),
//                            texels.size() * sizeof(float));
//     // sets.bindImage(resource, lut.view(), lut.sampler());  (prism/vk/pipeline.hpp)
//
// GL's texture parameters in Vulkan's words: `filter` is GL's MIN and MAG filter (no mipmaps),
// every axis clamps to the edge. The texel bytes must fill the image exactly (else
// std::invalid_argument). Move-only.
#pragma once

#include <cstddef>
#include <cstdint>

#include "prism/vk/device.hpp"
#include "prism/vk/handles.hpp"

namespace prism::vk {

struct TextureDescription {
    VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D;  // 2D, 2D_ARRAY or 3D
    int width = 1, height = 1;
    int depth = 1;  // layers of a 2D array, slices of a 3D image; 1 for 2D
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkFilter filter = VK_FILTER_NEAREST;
};

// Bytes per texel of the formats Texture uploads (RGBA32F, RG32F, R32F, R32UI, RGBA8);
// throws std::invalid_argument for any other.
std::size_t texelBytes(VkFormat format);

class Texture {
  public:
    Texture(const Device& device, const TextureDescription& description, const void* texels, std::size_t bytes);

    VkImage image() const { return image_.get(); }
    VkImageView view() const { return view_.get(); }
    VkSampler sampler() const { return sampler_.get(); }
    const TextureDescription& description() const { return description_; }

  private:
    TextureDescription description_;
    Memory memory_;  // declared first: destroyed after the image bound to it
    ImageObject image_;
    ImageView view_;
    Sampler sampler_;
};

}  // namespace prism::vk
