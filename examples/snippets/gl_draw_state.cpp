// The usage example of prism/gl/draw_state.hpp, compiled and run by tests/snippets.
#include <string>

#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"

// [snippet]
#include "prism/gl/draw_state.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    prism::gl::DrawState before = prism::gl::DrawState::capture();
    {
        prism::gl::ScopedDrawState keep;  // restored when the scope ends
        glEnable(GL_BLEND);
    }
    std::string changed = prism::gl::describeChanges(before, prism::gl::DrawState::capture());  // ""
    // [/snippet]
    return changed.empty() && !glIsEnabled(GL_BLEND) ? 0 : 1;
}
