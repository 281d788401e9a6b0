// Shared pieces of the rendering-tier tests: the catalogue shaders as the tests iterate
// them (phong twice: plain and BLINN=1), the brightest value each shader may write, the
// program cache of a GlTest suite, and small image helpers (coverage, largest channel).
#pragma once

#include <gtest/gtest.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "prism/image/image.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/view/lighting.hpp"

namespace prism::rendering_test {

// One catalogue shader as the tests see it. `label` names it in test output and is the
// directory of its golden images (tests/golden/<label>/).
struct ShaderSpec {
    std::string label;              // "phong-blinn"
    std::string shader;             // "phong"
    render::VariantValues variant;  // {{"BLINN", "1"}}
    bool lit = true;                // false: unicolor writes the material colour
    bool specular = true;           // false: flat and smooth are diffuse only
};

// unicolor, flat, smooth, gouraud, phong, phong-blinn.
const std::vector<ShaderSpec>& catalogueShaders();
const ShaderSpec& shaderSpec(const std::string& label);

// The brightest value `spec` may write per channel: the material colour for the unlit
// shader, view::maxRadiance(lights, material) for the specular ones, and maxRadiance with the
// specular strength zeroed for the diffuse-only ones (a tighter bound that also catches
// a specular term leaking into flat or smooth shading).
glm::vec3 brightestAllowed(const ShaderSpec& spec, const view::Lights& lights, const view::Material& material);

// The running GlTest suite's program cache of the catalogue shaders.
render::ProgramCache& programCache();

// A render::RenderJob for `spec` with the mesh prepared for its shader.
render::RenderJob jobFor(const ShaderSpec& spec, const geometry::Mesh& mesh, int width, int height);

// Pixels whose RGB differs from `background` by more than `tolerance` in any channel.
std::size_t coveredPixels(const image::ImageF& image, const glm::vec4& background, float tolerance = 1e-4f);
std::size_t coveredPixels(const image::Image8& image, const glm::vec4& background, int tolerance = 1);

// What a render must never contain, counted over all pixels of an RGBA32F image.
struct PixelInspection {
    std::size_t nonFinite = 0;    // a channel is NaN or Inf
    std::size_t overBright = 0;   // an RGB channel above bound + epsilon, or alpha above 1 + epsilon
    std::size_t negative = 0;     // a channel below -1e-6
    std::string firstOverBright;  // "pixel (x, y) channel c = v > limit", for messages
    std::string firstNegative;
};
PixelInspection inspectPixels(const image::ImageF& image, const glm::vec3& bound, float epsilon);

}  // namespace prism::rendering_test
