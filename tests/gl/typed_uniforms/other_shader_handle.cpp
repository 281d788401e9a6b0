// Must not compile (tests/gl/CMakeLists.txt): a unicolor program takes no phong handle, even
// one whose name and type unicolor also has.
#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

void setUnicolor(prism::gl::Program& program) {
    prism::gl::ProgramOf<prism::shaders::unicolor::Shader> unicolor(program);
    unicolor.set(prism::shaders::phong::u_color, glm::vec4(1.0f));
}
