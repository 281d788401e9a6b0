// The usage example of prism/render/feature_variants.hpp, compiled and run by tests/snippets.
#include "prism/shaders.hpp"
// [snippet]
#include "prism/render/feature_variants.hpp"
// [/snippet]

int main() {
    const prism::catalog::Catalog& cat = prism::shaders::kCatalog;
    prism::view::Lights lights;
    lights.directional.push_back({});
    const std::optional<prism::view::Fog> fog;
    // [snippet]
    prism::render::FeatureSet f = prism::render::featuresOf(lights, fog.has_value());
    const prism::catalog::Shader& phong = *prism::catalog::findShader(cat, "phong");
    prism::render::VariantValues v = prism::render::variantFor(phong, f, {{"BLINN", "1"}});
    // v == {BLINN=1, FOG=0, DIRECTIONAL_LIGHTS=1, POINT_LIGHTS=0} for one light, no fog
    // [/snippet]
    const prism::render::VariantValues expected{
        {"BLINN", "1"}, {"FOG", "0"}, {"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "0"}};
    return v == expected ? 0 : 1;
}
