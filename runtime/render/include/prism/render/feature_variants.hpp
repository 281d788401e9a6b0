// From what a scene needs to the shader variant that has exactly that: the "model only
// what the scene requires" rule. The feature set of a draw is the number of
// directional and point lights and whether there is fog; a shader's axes
// DIRECTIONAL_LIGHTS, POINT_LIGHTS (numeric: the smallest generated value that holds
// the scene's count, so the light loop is bounded by it) and FOG (0/1) are set from it.
// Other axes keep the values asked for, else their first value.
//
// Usage (snippet: examples/snippets/render_feature_variants.cpp):
//
//     #include "prism/render/feature_variants.hpp"
//     prism::render::FeatureSet f = prism::render::featuresOf(lights, fog.has_value());
//     const prism::catalog::Shader& phong = *prism::catalog::findShader(cat, "phong");
//     prism::render::VariantValues v = prism::render::variantFor(phong, f, {{"BLINN", "1"}});
//     // v == {BLINN=1, FOG=0, DIRECTIONAL_LIGHTS=1, POINT_LIGHTS=0} for one light, no fog
//
// Throws std::invalid_argument when a scene needs more lights than any variant holds.
#pragma once

#include <string>

#include "prism/render/program_cache.hpp"
#include "prism/view/lighting.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::render {

struct FeatureSet {
    int directionalLights = 0;
    int pointLights = 0;
    bool fog = false;
    bool operator==(const FeatureSet&) const = default;
};

FeatureSet featuresOf(const view::Lights& lights, bool fog);

VariantValues variantFor(const catalog::Shader& shader, const FeatureSet& features,
                         const VariantValues& requested = {});

}  // namespace prism::render
