// The usage example of prism/gl/program.hpp, compiled and run by tests/snippets. It must
// compile with only program.hpp and the catalogue included (glm::vec3/vec4, std::span).
#include "prism/gl/gl_context.hpp"
// [snippet]
#include <vector>

#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"  // generated catalogue
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const auto* variant = prism::catalog::findVariant(phong, {{"FOG", "1"}, {"DIRECTIONAL_LIGHTS", "4"}});
    if (variant == nullptr) return 1;  // not generated; a misspelled axis or value throws instead
    prism::gl::Program program(*variant, prism::shaders::kCatalog.contractAttributes, "phong");

    program.use();
    program.set("u_color", glm::vec4(1, 0, 0, 1));
    std::vector<glm::vec3> dirs{{0, -1, 0}, {1, -1, 0}};
    program.set("u_lightDirection", std::span<const glm::vec3>(dirs));  // array from element 0
    program.set("u_lightDirection[2]", glm::vec3(0, 1, 0));             // one element
    // [/snippet]
    return program.unknownUniformReports().empty() && program.typeMismatchReports().empty() ? 0 : 1;
}
