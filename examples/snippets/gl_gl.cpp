// The usage example of prism/gl/gl.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"  // the glad GL 4.5 core loader header
#include "prism/gl/gl_context.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto ctx = prism::gl::createContext();  // makes the context current and loads GL
    prism::gl::Framebuffer target(64, 64);  // EGL surfaceless has no default framebuffer
    target.bind();
    glClearColor(0.f, 0.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    prism::gl::throwIfGlError("clearing the frame");  // throws prism::gl::GlError
    // [/snippet]
    try {
        glEnable(0x1234);  // an invalid enum: the check must throw
        prism::gl::throwIfGlError("an invalid glEnable");
    } catch (const prism::gl::GlError&) {
        return 0;
    }
    return 1;
}
