// Typed uniforms that must compile (tests/gl/CMakeLists.txt): the control for the
// compile-fail cases beside it, so that their failure is the handle's doing.
#include <vector>

#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

void setPhong(prism::gl::Program& program) {
    namespace phong = prism::shaders::phong;
    program.set(phong::u_shininess, 32.0f);
    program.set(phong::u_color, glm::vec4(1.0f));
    std::vector<glm::vec3> directions{{0, -1, 0}, {1, -1, 0}};
    program.set(phong::u_lightDirection, directions);
    prism::gl::ProgramOf<phong::Shader> typed(program);
    typed.set(phong::u_world, glm::mat4(1.0f));
}
