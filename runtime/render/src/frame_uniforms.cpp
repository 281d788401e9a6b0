// The contract's uniforms from camera, lights, world matrix and material, for a GL program
// or a Vulkan uniform block: one template, so both APIs get the same values.
#include "prism/render/frame_uniforms.hpp"

#include <glm/mat3x3.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "prism/geometry/normal_matrix.hpp"
#include "prism/shaders.hpp"

namespace prism::render {
namespace {

namespace contract = shaders::contract;

// The number of elements of a uniform array (the program answers to a[0]..a[n-1]).
template <class Target>
int capacityOf(const Target& p, std::string_view arrayName) {
    int n = 0;
    while (n < 1024 && p.hasUniform(std::string(arrayName) + "[" + std::to_string(n) + "]")) ++n;
    return n;
}

// One kind of light: its count and two arrays of vec3 (direction or position, colour).
template <class Target, class Count, class Array>
void setLightArray(Target& p, const Count& count, const Array& firstArray, const Array& secondArray,
                   const std::vector<glm::vec3>& first, const std::vector<glm::vec3>& second) {
    if (!p.hasUniform(count.name)) return;
    const int capacity = capacityOf(p, firstArray.name);
    if (static_cast<int>(first.size()) > capacity)
        throw std::invalid_argument(p.label() + ": " + std::to_string(first.size()) +
                                    " lights given but the shader holds " + std::to_string(capacity) + " (" +
                                    std::string(firstArray.name) + "); choose a variant with more lights");
    p.set(count, static_cast<int>(first.size()));
    if (first.empty()) return;
    p.set(firstArray, first);
    p.set(secondArray, second);
}

// `Target` is gl::Program or vk::UniformBlock: set(handle, value), hasUniform(name), label().
template <class Target>
void setContractUniforms(Target& p, const view::Camera& camera, float aspect, const view::Lights& lights,
                         const glm::mat4& world, const view::Material& material, const view::Fog* fog) {
    const glm::mat4 view = camera.view();
    p.set(contract::u_world, world);
    p.set(contract::u_view, view);
    p.set(contract::u_projection, camera.projection(aspect));
    p.set(contract::u_normal, geometry::normalMatrix(view * world));
    p.set(contract::u_color, material.color);
    p.set(contract::u_shininess, material.shininess);
    p.set(contract::u_specular, material.specular);
    p.set(contract::u_ambient, lights.ambient);
    if (fog && !(fog->density >= 0.0f)) throw std::invalid_argument(p.label() + ": fog density must be a number >= 0");
    p.set(contract::u_fogColor, fog ? fog->color : glm::vec3(0.0f));
    p.set(contract::u_fogDensity, fog ? fog->density : 0.0f);

    std::vector<glm::vec3> directions, colors, positions, pointColors;
    for (const auto& l : lights.directional) {
        directions.push_back(l.direction);
        colors.push_back(l.color);
    }
    for (const auto& l : lights.points) {
        positions.push_back(l.position);
        pointColors.push_back(l.color);
    }
    setLightArray(p, contract::u_directionalLightCount, contract::u_lightDirection, contract::u_lightColor, directions,
                  colors);
    setLightArray(p, contract::u_pointLightCount, contract::u_pointLightPosition, contract::u_pointLightColor,
                  positions, pointColors);
}

}  // namespace

void setFrameUniforms(gl::Program& program, const view::Camera& camera, float aspect, const view::Lights& lights,
                      const glm::mat4& world, const view::Material& material, const view::Fog* fog) {
    setContractUniforms(program, camera, aspect, lights, world, material, fog);
}

void setFrameUniforms(vk::UniformBlock& block, const view::Camera& camera, float aspect, const view::Lights& lights,
                      const glm::mat4& world, const view::Material& material, const view::Fog* fog) {
    setContractUniforms(block, camera, aspect, lights, world, material, fog);
}

}  // namespace prism::render
