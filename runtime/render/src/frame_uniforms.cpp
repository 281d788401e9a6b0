// The contract's uniforms from camera, lights, world matrix and material.
#include "prism/render/frame_uniforms.hpp"

#include <glm/mat3x3.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "prism/geometry/normal_matrix.hpp"

namespace prism::render {
namespace {

template <class T>
void setIfPresent(gl::Program& p, std::string_view name, const T& value) {
    if (p.hasUniform(name)) p.set(name, value);
}

// The number of elements of a uniform array (the program answers to a[0]..a[n-1]).
int capacityOf(const gl::Program& p, std::string_view arrayName) {
    int n = 0;
    while (n < 1024 && p.hasUniform(std::string(arrayName) + "[" + std::to_string(n) + "]")) ++n;
    return n;
}

void setLightArray(gl::Program& p, std::string_view countName, std::string_view firstName, std::string_view secondName,
                   const std::vector<glm::vec3>& first, const std::vector<glm::vec3>& second) {
    if (!p.hasUniform(countName)) return;
    const int capacity = capacityOf(p, firstName);
    if (static_cast<int>(first.size()) > capacity)
        throw std::invalid_argument(p.label() + ": " + std::to_string(first.size()) +
                                    " lights given but the shader holds " + std::to_string(capacity) + " (" +
                                    std::string(firstName) + "); choose a variant with more lights");
    p.set(countName, static_cast<int>(first.size()));
    if (first.empty()) return;
    p.set(firstName, std::span<const glm::vec3>(first));
    p.set(secondName, std::span<const glm::vec3>(second));
}

}  // namespace

void setFrameUniforms(gl::Program& p, const view::Camera& camera, float aspect, const view::Lights& lights,
                      const glm::mat4& world, const view::Material& material, const view::Fog* fog) {
    const glm::mat4 view = camera.view();
    setIfPresent(p, "u_world", world);
    setIfPresent(p, "u_view", view);
    setIfPresent(p, "u_projection", camera.projection(aspect));
    setIfPresent(p, "u_normal", geometry::normalMatrix(view * world));
    setIfPresent(p, "u_color", material.color);
    setIfPresent(p, "u_shininess", material.shininess);
    setIfPresent(p, "u_specular", material.specular);
    setIfPresent(p, "u_ambient", lights.ambient);
    if (fog && !(fog->density >= 0.0f)) throw std::invalid_argument(p.label() + ": fog density must be a number >= 0");
    setIfPresent(p, "u_fogColor", fog ? fog->color : glm::vec3(0.0f));
    setIfPresent(p, "u_fogDensity", fog ? fog->density : 0.0f);

    std::vector<glm::vec3> directions, colors, positions, pointColors;
    for (const auto& l : lights.directional) {
        directions.push_back(l.direction);
        colors.push_back(l.color);
    }
    for (const auto& l : lights.points) {
        positions.push_back(l.position);
        pointColors.push_back(l.color);
    }
    setLightArray(p, "u_directionalLightCount", "u_lightDirection", "u_lightColor", directions, colors);
    setLightArray(p, "u_pointLightCount", "u_pointLightPosition", "u_pointLightColor", positions, pointColors);
}

}  // namespace prism::render
