// GL function access for code that calls OpenGL directly, plus GL error checks.
//
// Usage (snippet: examples/snippets/gl_gl.cpp):
//
//     #include "prism/gl/framebuffer.hpp"
//     #include "prism/gl/gl.hpp"  // the glad GL 4.5 core loader header
//     #include "prism/gl/gl_context.hpp"
//     auto ctx = prism::gl::createContext();  // makes the context current and loads GL
//     prism::gl::Framebuffer target(64, 64);  // EGL surfaceless has no default framebuffer
//     target.bind();
//     glClearColor(0.f, 0.f, 0.f, 1.f);
//     glClear(GL_COLOR_BUFFER_BIT);
//     prism::gl::throwIfGlError("clearing the frame");  // throws prism::gl::GlError
//
// Function pointers are loaded by Context::makeCurrent() (and by createContext), so
// include this header only in code that runs with a current context. Never include
// <GL/gl.h> or <GL/osmesa.h> in the same file: they clash with the loader header.
#pragma once

#include <glad/gl.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace prism::gl {

class GlError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// "GL_INVALID_OPERATION" etc. for a glGetError() value.
std::string_view glErrorName(GLenum error);

// Drains glGetError(); throws GlError naming `what` and every pending error.
void throwIfGlError(std::string_view what);

}  // namespace prism::gl
