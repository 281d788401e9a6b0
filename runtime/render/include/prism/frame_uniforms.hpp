// Sets the engine-provided uniforms of the binding contract (modules/contract.json)
// on a program: transforms from the camera and world matrix, the eye-space normal
// matrix, lights, material and (for FOG variants) fog. Only uniforms the program actually has are set.
//
//     prism::setFrameUniforms(program, camera, aspect, lights, world, material);
//     gpuMesh.draw();
//
// More lights than the program's arrays hold is an error (std::invalid_argument)
// naming the shader's capacity, never a silent truncation.
#pragma once

#include <glm/mat4x4.hpp>

#include "prism/camera.hpp"
#include "prism/program.hpp"
#include "prism/scene_lighting.hpp"

namespace prism {

void setFrameUniforms(gl::Program& program, const Camera& camera, float aspect, const Lights& lights,
                      const glm::mat4& world, const Material& material, const Fog* fog = nullptr);

}  // namespace prism
