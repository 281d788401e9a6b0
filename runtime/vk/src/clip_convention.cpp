// GL's clip-space conventions on Vulkan (see prism/vk/clip_convention.hpp for the table).
#include "prism/vk/clip_convention.hpp"

namespace prism::vk {

VkViewport ClipConvention::viewport(int width, int height) const {
    VkViewport v{};
    v.x = 0.0f;
    v.width = static_cast<float>(width);
    v.y = negativeViewport() ? static_cast<float>(height) : 0.0f;
    v.height = negativeViewport() ? -static_cast<float>(height) : static_cast<float>(height);
    v.minDepth = 0.0f;
    v.maxDepth = 1.0f;
    return v;
}

VkFrontFace ClipConvention::frontFace() const {
    // Vulkan computes facing in framebuffer coordinates (y down), after the viewport: the
    // flip turns a triangle counter-clockwise in GL's y-up window into one counter-clockwise
    // there too. Without the flip (a fault) every facing is reversed as well. In GL's row
    // order framebuffer y points up, as GL's window y, so GL's counter-clockwise is Vulkan's
    // clockwise there.
    return glRowOrder ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
}

void ClipConvention::chainDepthRange(VkPipelineViewportStateCreateInfo& state,
                                     VkPipelineViewportDepthClipControlCreateInfoEXT& control) const {
    control = {VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_DEPTH_CLIP_CONTROL_CREATE_INFO_EXT};
    control.negativeOneToOne = glDepth ? VK_TRUE : VK_FALSE;
    control.pNext = state.pNext;
    state.pNext = &control;
}

void ClipConvention::chainProvokingVertex(VkPipelineRasterizationStateCreateInfo& state,
                                          VkPipelineRasterizationProvokingVertexStateCreateInfoEXT& provoking) const {
    provoking = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_PROVOKING_VERTEX_STATE_CREATE_INFO_EXT};
    provoking.provokingVertexMode =
        glProvokingVertex ? VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT : VK_PROVOKING_VERTEX_MODE_FIRST_VERTEX_EXT;
    provoking.pNext = state.pNext;
    state.pNext = &provoking;
}

}  // namespace prism::vk
