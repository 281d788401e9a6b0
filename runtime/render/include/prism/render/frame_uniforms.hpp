// Sets the engine-provided uniforms of the binding contract (modules/contract.json)
// on a program: transforms from the camera and world matrix, the eye-space normal
// matrix, lights, material and (for FOG variants) fog. Only uniforms the program actually has are set.
// The same values fill a Vulkan draw's uniform block by name (prism/vk/uniform_block.hpp):
// both overloads run one function, so GL and Vulkan get the same numbers.
//
// Usage (snippet: examples/snippets/render_frame_uniforms.cpp):
//
//     #include "prism/render/frame_uniforms.hpp"
//     prism::render::setFrameUniforms(program, camera, aspect, lights, world, material);
//     gpuMesh.draw();
//
// More lights than the program's arrays hold is an error (std::invalid_argument)
// naming the shader's capacity, never a silent truncation.
#pragma once

#include <glm/mat4x4.hpp>

#include "prism/view/camera.hpp"
#include "prism/gl/program.hpp"
#include "prism/view/lighting.hpp"
#include "prism/vk/uniform_block.hpp"

namespace prism::render {

void setFrameUniforms(gl::Program& program, const view::Camera& camera, float aspect, const view::Lights& lights,
                      const glm::mat4& world, const view::Material& material, const view::Fog* fog = nullptr);
void setFrameUniforms(vk::UniformBlock& block, const view::Camera& camera, float aspect, const view::Lights& lights,
                      const glm::mat4& world, const view::Material& material, const view::Fog* fog = nullptr);

}  // namespace prism::render
