// Must not compile (tests/gl/CMakeLists.txt): u_shininess is a GLSL float, not an int.
#include "prism/gl/program.hpp"
#include "prism/shaders.hpp"

void setPhong(prism::gl::Program& program) {
    program.set(prism::shaders::phong::u_shininess, 32);
}
