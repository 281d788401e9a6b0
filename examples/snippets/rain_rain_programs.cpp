// The usage example of prism/rain/rain_programs.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/rain/rain_programs.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    // [snippet]
    prism::rain::RainPrograms programs;
    prism::gl::Program& p = programs.get("ground", {{"FOG", "0"}});
    programs.used();  // {"ground (FOG=0)"}
    // [/snippet]
    return p.id() != 0 && programs.used().size() == 1 ? 0 : 1;
}
