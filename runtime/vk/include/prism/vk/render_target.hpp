// An off-screen target: one RGBA8 colour image and a 32-bit float depth image with the
// render pass and framebuffer that draw into them, read back into a prism::image::Image8.
//
// Usage (snippet: examples/snippets/vk_render_target.cpp):
//
//     #include "prism/vk/render_target.hpp"
//     prism::vk::Device device;
//     prism::vk::RenderTarget target(device, 160, 120);
//     device.submit([&](VkCommandBuffer cmd) {
//         target.begin(cmd, {0.05f, 0.06f, 0.08f, 1.0f});  // clears colour and depth (1.0)
//         // bind a pipeline and draw (prism/vk/pipeline.hpp)
//         target.end(cmd);
//     });
//     prism::image::Image8 image = target.readImage8();  // row 0 at the top, like GL's after its flip
//
// The colour image is R8G8B8A8_UNORM, as GL's RGBA8 framebuffer, so both APIs round the
// shaders' floats to the same bytes; or R32G32B32A32_SFLOAT (kFloatColorFormat, read with
// readImageF), as GL's RGBA32F one, for values that must not be clamped. Move-only.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "prism/image/image.hpp"
#include "prism/vk/clip_convention.hpp"
#include "prism/vk/device.hpp"
#include "prism/vk/handles.hpp"

namespace prism::vk {

class RenderTarget {
  public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kFloatColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    // Throws std::invalid_argument for a size outside 1..16384 or another colour format.
    RenderTarget(const Device& device, int width, int height, VkFormat colorFormat = kColorFormat);

    int width() const { return width_; }
    int height() const { return height_; }
    VkRenderPass renderPass() const { return renderPass_.get(); }

    // Begins the render pass, clearing colour to `clear` and depth to 1.
    void begin(VkCommandBuffer cmd, const std::array<float, 4>& clear) const;
    void end(VkCommandBuffer cmd) const;

    VkFormat colorFormat() const { return colorFormat_; }

    // Copies the colour image to the CPU (submits and waits): rows top to bottom, also when
    // `clip` stores them in GL's order (ClipConvention::glRowOrder). readImage8 needs the
    // RGBA8 format, readImageF the float one (else std::logic_error).
    image::Image8 readImage8(const ClipConvention& clip = {}) const;
    image::ImageF readImageF(const ClipConvention& clip = {}) const;

  private:
    // The colour image's bytes, rows top to bottom.
    std::vector<std::byte> readBytes(VkFormat expected, const ClipConvention& clip) const;

    const Device* device_;
    int width_, height_;
    VkFormat colorFormat_;
    Memory colorMemory_, depthMemory_;
    ImageObject color_, depth_;
    ImageView colorView_, depthView_;
    RenderPass renderPass_;
    FramebufferObject framebuffer_;
};

}  // namespace prism::vk
