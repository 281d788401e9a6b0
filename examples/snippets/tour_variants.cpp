// docs/runtime.md, "Variants from lights": from the lights (and fog) a scene has to the
// variant with exactly that. Compiled and run by tests/snippets (snippets.tour_variants).
// [snippet]
#include <iostream>

#include "prism/render/feature_variants.hpp"
#include "prism/shaders.hpp"
#include "prism/view/lighting.hpp"

int main() {
    prism::view::Lights lights;
    lights.ambient = {0.1f, 0.1f, 0.1f};
    lights.directional.push_back({.direction = {-1, -1, -1}, .color = {1, 1, 1}});
    lights.directional.push_back({.direction = {1, -0.5f, 0}, .color = {0.3f, 0.3f, 0.5f}});

    // Two directional lights, no point light, no fog ...
    prism::render::FeatureSet features = prism::render::featuresOf(lights, /*fog*/ false);
    // ... pick DIRECTIONAL_LIGHTS=2 (the smallest generated value that holds 2), POINT_LIGHTS=0,
    // FOG=0; axes that lights do not decide keep what you ask for (BLINN=1).
    const prism::catalog::Shader& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    prism::render::VariantValues values = prism::render::variantFor(phong, features, {{"BLINN", "1"}});
    const prism::catalog::Variant* variant = prism::catalog::findVariant(phong, values);
    if (variant == nullptr) return 1;  // those values exist, but the build did not generate them (VARIANTS)
    std::cout << "phong " << variant->name << "\n";  // BLINN=1,FOG=0,DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=0

    // A misspelled axis or value is an error that names it and lists the known ones.
    try {
        prism::catalog::findVariant(phong, {{"DIRECTIONAL_LIGHT", "1"}});
        return 1;
    } catch (const prism::catalog::VariantLookupError& e) {
        // shader 'phong' has no variant axis 'DIRECTIONAL_LIGHT' (did you mean 'DIRECTIONAL_LIGHTS'?); its axes: ...
        std::cout << e.what() << "\n";
    }
    return 0;
}
// [/snippet]
