// The usage example of prism/gl/gl_context.hpp, compiled and run by tests/snippets
// (headless: the GLFW window fails without a display and says what to run instead).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto ctx = prism::gl::createContext();      // EGL, else OSMesa
    std::cout << ctx->info().renderer << "\n";  // "llvmpipe (LLVM 15.0.6, 256 bits)"
    try {
        auto win = prism::gl::createContext(prism::gl::Backend::Glfw, {.width = 800, .height = 600});
    } catch (const prism::gl::ContextError& e) {  // no display: run under xvfb-run
        std::cerr << e.what() << "\n";
    }
    ctx->makeCurrent();  // before GL calls when several contexts exist; reloads GL if needed
    // [/snippet]
    return ctx->isCurrent() ? 0 : 1;
}
