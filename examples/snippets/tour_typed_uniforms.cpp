// docs/runtime.md, "Typed uniforms": set a program's uniforms through the handles its
// generated header declares, and list the ones never set. Compiled and run by tests/snippets
// (snippets.tour_typed_uniforms).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

int main() {
    auto context = prism::gl::createContext();
    const auto& shader = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const auto* variant = prism::catalog::findVariant(shader, {});
    if (variant == nullptr) return 1;
    prism::gl::Program program(*variant, prism::shaders::kCatalog.contractAttributes, "phong");

    // prism::shaders::phong holds a typed constant for every uniform of any phong variant.
    namespace phong = prism::shaders::phong;
    prism::gl::ProgramOf<phong::Shader> typed(program);  // takes phong's handles, no other shader's
    typed.set(phong::u_shininess, 32.0f);                // a GLSL float: 32 (an int) would not compile
    typed.set(phong::u_color, glm::vec4(0.2f, 0.5f, 0.9f, 1.0f));

    // Active uniforms never set since link (samplers and uniforms with an initialiser left
    // out). In debug builds GpuMesh::draw warns about each once, before the first draw.
    for (const std::string& name : program.unsetUniforms()) std::cout << "never set: " << name << "\n";
    return program.unsetUniforms().empty() ? 1 : 0;  // the transforms and lights are still unset here
}
// [/snippet]
