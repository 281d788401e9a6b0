// The usage example of prism/catalog/shader_catalog.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/shaders.hpp"  // generated
// [/snippet]

int main() {
    // [snippet]
    const auto& s = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    // A misspelled axis or value throws VariantLookupError naming it and the known ones;
    // nullptr means known values whose combination was not generated (VARIANTS).
    const auto* v = prism::catalog::findVariant(s, {{"BLINN", "1"}});
    if (v == nullptr) return 1;
    std::string vert = prism::catalog::joinChunks(v->stages[0].chunks);
    // [/snippet]
    return vert.rfind("#version", 0) == 0 ? 0 : 1;
}
