// docs/runtime.md, "A program from a catalogue": look a shader and a variant up in a
// generated catalogue and link it. Compiled and run by tests/snippets (snippets.tour_program).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

int main() {
    auto context = prism::gl::createContext();

    // Every shader of the catalogue, with its variant axes (from `#pragma prism variant`).
    for (const prism::catalog::Shader& shader : prism::shaders::kCatalog.shaders)
        std::cout << shader.name << ": " << shader.variants.size() << " variants\n";

    // One variant of one shader: the values not named here take their axis's first value.
    const prism::catalog::Shader& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const prism::catalog::Variant* variant = prism::catalog::findVariant(phong, {{"BLINN", "1"}});
    if (variant == nullptr) return 1;  // not generated; a misspelled axis or value throws VariantLookupError
    std::cout << "building phong " << variant->name << "\n";

    // Compiles every stage, binds the contract's attribute locations, links. A GLSL error
    // throws prism::gl::ShaderBuildError with `modules/lights.glsl:12:3: error: ...` lines.
    prism::gl::Program program(*variant, prism::shaders::kCatalog.contractAttributes, "phong");
    return program.id() != 0 ? 0 : 1;
}
// [/snippet]
