// The off-screen colour and depth target, its render pass and read-back (see
// prism/vk/render_target.hpp).
#include "prism/vk/render_target.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "prism/vk/buffer.hpp"

namespace prism::vk {
namespace {

ImageObject createImage(const Device& device, VkFormat format, VkImageUsageFlags usage, int width, int height,
                        Memory& memory) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return createDeviceImage(device, info, memory);
}

ImageView createView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {aspect, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device.device(), &info, nullptr, &view), "vkCreateImageView");
    return ImageView(device.device(), view);
}

// Colour: cleared, stored, left ready to copy from. Depth: cleared, not kept.
RenderPass createRenderPass(const Device& device, VkFormat colorFormat) {
    VkAttachmentDescription attachments[2]{};
    attachments[0].format = colorFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments[1] = attachments[0];
    attachments[1].format = RenderTarget::kDepthFormat;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;
    // The copy after the pass waits for the colour writes.
    VkSubpassDependency after{};
    after.srcSubpass = 0;
    after.dstSubpass = VK_SUBPASS_EXTERNAL;
    after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &after;
    VkRenderPass pass = VK_NULL_HANDLE;
    check(vkCreateRenderPass(device.device(), &info, nullptr, &pass), "vkCreateRenderPass");
    return RenderPass(device.device(), pass);
}

}  // namespace

RenderTarget::RenderTarget(const Device& device, int width, int height, VkFormat colorFormat)
    : device_(&device), width_(width), height_(height), colorFormat_(colorFormat) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw std::invalid_argument("render size must be between 1x1 and 16384x16384, not " + std::to_string(width) +
                                    "x" + std::to_string(height));
    if (colorFormat != kColorFormat && colorFormat != kFloatColorFormat)
        throw std::invalid_argument("prism::vk::RenderTarget: the colour format must be RGBA8 or RGBA32F");
    color_ = createImage(device, colorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         width, height, colorMemory_);
    depth_ =
        createImage(device, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, width, height, depthMemory_);
    colorView_ = createView(device, color_.get(), colorFormat, VK_IMAGE_ASPECT_COLOR_BIT);
    depthView_ = createView(device, depth_.get(), kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT);
    renderPass_ = createRenderPass(device, colorFormat);
    VkImageView views[] = {colorView_.get(), depthView_.get()};
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_.get();
    info.attachmentCount = 2;
    info.pAttachments = views;
    info.width = static_cast<std::uint32_t>(width);
    info.height = static_cast<std::uint32_t>(height);
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(device.device(), &info, nullptr, &framebuffer), "vkCreateFramebuffer");
    framebuffer_ = FramebufferObject(device.device(), framebuffer);
}

void RenderTarget::begin(VkCommandBuffer cmd, const std::array<float, 4>& clear) const {
    VkClearValue clears[2]{};
    std::memcpy(clears[0].color.float32, clear.data(), sizeof(float) * 4);
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = renderPass_.get();
    info.framebuffer = framebuffer_.get();
    info.renderArea = {{0, 0}, {static_cast<std::uint32_t>(width_), static_cast<std::uint32_t>(height_)}};
    info.clearValueCount = 2;
    info.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void RenderTarget::end(VkCommandBuffer cmd) const {
    vkCmdEndRenderPass(cmd);
}

std::vector<std::byte> RenderTarget::readBytes(VkFormat expected, const ClipConvention& clip) const {
    if (colorFormat_ != expected)
        throw std::logic_error(
            "prism::vk::RenderTarget: read back as the wrong format (readImage8 for RGBA8, "
            "readImageF for RGBA32F)");
    const std::size_t rowBytes = static_cast<std::size_t>(width_) * (expected == kColorFormat ? 4 : 16);
    const std::size_t bytes = rowBytes * static_cast<std::size_t>(height_);
    Buffer readBack(*device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    device_->submit([&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {static_cast<std::uint32_t>(width_), static_cast<std::uint32_t>(height_), 1};
        vkCmdCopyImageToBuffer(cmd, color_.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readBack.get(), 1, &region);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                             0, nullptr);
    });
    std::vector<std::byte> out(bytes);
    for (std::size_t row = 0; row < static_cast<std::size_t>(height_); ++row) {  // row 0 at the top
        const std::size_t from = clip.glRowOrder ? static_cast<std::size_t>(height_) - 1 - row : row;
        std::memcpy(out.data() + row * rowBytes, readBack.data() + from * rowBytes, rowBytes);
    }
    return out;
}

image::Image8 RenderTarget::readImage8(const ClipConvention& clip) const {
    const std::vector<std::byte> bytes = readBytes(kColorFormat, clip);
    image::Image8 image(width_, height_);
    std::memcpy(image.data.data(), bytes.data(), bytes.size());
    return image;
}

image::ImageF RenderTarget::readImageF(const ClipConvention& clip) const {
    const std::vector<std::byte> bytes = readBytes(kFloatColorFormat, clip);
    image::ImageF image(width_, height_);
    std::memcpy(image.data.data(), bytes.data(), bytes.size());
    return image;
}

}  // namespace prism::vk
