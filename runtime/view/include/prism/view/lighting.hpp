// Lights, fog and materials as the catalogue shaders see them (modules/lights.glsl,
// modules/fog.glsl, modules/material.glsl): ambient + directional lights + point lights, and a material
// with colour, shininess (Phong exponent) and specular strength.
//
// Usage (snippet: examples/snippets/view_lighting.cpp):
//
//     #include "prism/view/lighting.hpp"
//     prism::view::Lights lights;
//     lights.ambient = {0.1f, 0.1f, 0.1f};
//     lights.directional.push_back({.direction = {-1, -1, -1}, .color = {1, 1, 1}});
//     prism::view::Material m{.color = {0.8f, 0.3f, 0.2f, 1.f}, .shininess = 32.f, .specular = 0.5f};
//     glm::vec3 brightest = prism::view::maxRadiance(lights, m);  // no lit pixel exceeds this
//
// Directions point from the light into the scene, in world space. Point lights have no
// distance falloff, so the brightest a lit pixel can be is
// maxRadiance(): ambient*colour + sum over lights of (colour + specular) * light colour.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace prism::view {

struct DirectionalLight {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    glm::vec3 color{1.0f};
};

struct PointLight {
    glm::vec3 position{0.0f, 2.0f, 0.0f};
    glm::vec3 color{1.0f};
};

struct Lights {
    glm::vec3 ambient{0.1f};
    std::vector<DirectionalLight> directional;
    std::vector<PointLight> points;
};

// Exponential distance fog (modules/fog.glsl); used only by a shader's FOG=1 variant.
struct Fog {
    glm::vec3 color{0.62f, 0.66f, 0.72f};
    float density = 0.15f;  // per unit of eye distance; >= 0
};

struct Material {
    glm::vec4 color{0.8f, 0.8f, 0.8f, 1.0f};
    float shininess = 32.0f;
    float specular = 0.5f;
};

// Upper bound of any channel of a lit pixel (before the framebuffer clamps it).
inline glm::vec3 maxRadiance(const Lights& lights, const Material& m) {
    glm::vec3 bound = lights.ambient * glm::vec3(m.color);
    for (const auto& l : lights.directional) bound += (glm::vec3(m.color) + glm::vec3(m.specular)) * l.color;
    for (const auto& l : lights.points) bound += (glm::vec3(m.color) + glm::vec3(m.specular)) * l.color;
    return bound;
}

}  // namespace prism::view
