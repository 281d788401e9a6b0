// GL's clip space and window conventions on Vulkan, in this one place, so that the
// catalogue's SPIR-V (compiled from the same GL-style modules as the GL text) draws the
// same picture through both APIs without touching a shader or a matrix:
//
// | convention            | GL                         | Vulkan default              | here                        |
// |-----------------------|----------------------------|-----------------------------|-----------------------------|
// | clip-space +y         | up                         | down                        | viewport of negative height |
// | clip-space depth      | -1..1 -> window 0..1       | 0..1, below 0 clipped       | VK_EXT_depth_clip_control   |
// | front face            | counter-clockwise (window) | as set; y flip mirrors it   | counter-clockwise           |
// | read-back row 0       | bottom                     | top                         | top, as prism::image        |
// | flat shading's vertex | the last of the triangle   | the first                   | VK_EXT_provoking_vertex     |
//
// The negative height (core since Vulkan 1.1) puts NDC y = +1 at row 0, the top, so the
// winding a GL programmer sees is kept and VK_FRONT_FACE_COUNTER_CLOCKWISE matches
// glFrontFace(GL_CCW). depth_clip_control's negativeOneToOne maps z = -1..1 to depth 0..1
// exactly as GL does, so depth values, near/far clipping and depth-test ties agree too
// (a projection matrix rewritten for 0..1 would change the float rounding of every depth).
// A `flat` output takes the provoking vertex's value: GL's is a triangle's last vertex,
// Vulkan's its first, unless VK_EXT_provoking_vertex says last (the flat shader's colour
// differs per vertex under a point light). `gl_FragCoord.y` counts from the top in Vulkan
// (OriginUpperLeft, which SPIR-V for Vulkan must use) and from the bottom in GL. A pass whose
// shader reads it (the blue-noise soft shadows) sets glRowOrder: the target's rows are then
// stored bottom-up as GL stores them, with no viewport flip (so row r has gl_FragCoord.y =
// r + 0.5 in both APIs), a clockwise front face (Vulkan's facing in those rows), and
// RenderTarget's read-back reverses the rows, as Prism's GL read-back does.
//
// Usage (snippet: examples/snippets/vk_clip_convention.cpp):
//
//     #include "prism/vk/clip_convention.hpp"
//     prism::vk::ClipConvention gl;                      // GL's conventions (the default)
//     VkViewport viewport = gl.viewport(160, 120);       // y = 120, height = -120
//     prism::vk::ClipConvention broken{.flipY = false};  // a fault for the tests that must catch it
//
// glRowOrder chooses the row order; the other members exist to inject faults: the agreement
// tests show a wrong y flip, a wrong depth range or the wrong provoking vertex fails them
// (docs/vulkan.md).
#pragma once

#include <vulkan/vulkan.h>

namespace prism::vk {

struct ClipConvention {
    bool flipY = true;              // false: Vulkan's y down (GL images upside down)
    bool glDepth = true;            // false: Vulkan's 0..1 depth (GL's near half clipped away)
    bool glProvokingVertex = true;  // false: Vulkan's first vertex feeds `flat` outputs
    bool glRowOrder = false;        // true: rows bottom-up as GL's, for shaders that read gl_FragCoord

    // Whether the viewport has a negative height: flipY, unless the rows are GL's already.
    bool negativeViewport() const { return flipY != glRowOrder; }

    // The viewport for a `width` x `height` target.
    VkViewport viewport(int width, int height) const;
    // GL's default front face, glFrontFace(GL_CCW), in Vulkan's terms under the flip.
    VkFrontFace frontFace() const;
    // Chains `control` (which must outlive the pipeline's creation) into `state`.
    void chainDepthRange(VkPipelineViewportStateCreateInfo& state,
                         VkPipelineViewportDepthClipControlCreateInfoEXT& control) const;
    // Chains `provoking` (which must outlive the pipeline's creation) into `state`.
    void chainProvokingVertex(VkPipelineRasterizationStateCreateInfo& state,
                              VkPipelineRasterizationProvokingVertexStateCreateInfoEXT& provoking) const;
};

}  // namespace prism::vk
