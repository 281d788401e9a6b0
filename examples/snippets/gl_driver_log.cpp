// The usage example of prism/gl/driver_log.hpp, compiled and run by tests/snippets.
// [snippet]
#include <vector>

#include "prism/gl/driver_log.hpp"
// [/snippet]

int main() {
    const std::string log = "1:12(3): error: `foo' undeclared\n";  // as Mesa reports it
    // [snippet]
    std::vector<prism::gl::SourceName> files{{0, "shaders/phong.frag"}, {1, "modules/lights.glsl"}};
    std::string nice = prism::gl::translateDriverLog(log, files);
    // "1:12(3): error: `foo' undeclared"  ->  "modules/lights.glsl:12:3: error: `foo' undeclared"
    // [/snippet]
    return nice == "modules/lights.glsl:12:3: error: `foo' undeclared\n" ? 0 : 1;
}
