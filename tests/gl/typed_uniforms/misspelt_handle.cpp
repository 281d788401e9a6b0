// Must not compile (tests/gl/CMakeLists.txt): a misspelt uniform is no handle.
#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

void setPhong(prism::gl::Program& program) {
    program.set(prism::shaders::phong::u_colr, glm::vec4(1.0f));
}
