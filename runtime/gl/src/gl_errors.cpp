// Names of GL error codes and the error check used after GL calls.
#include "prism/gl/gl.hpp"

namespace prism::gl {

std::string_view glErrorName(GLenum error) {
    switch (error) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "unknown GL error";
    }
}

void throwIfGlError(std::string_view what) {
    std::string errors;
    for (int i = 0; i < 16; ++i) {  // bounded: a lost context can report errors forever
        const GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!errors.empty()) errors += ", ";
        errors += glErrorName(e);
    }
    if (!errors.empty()) throw GlError("GL error while " + std::string(what) + ": " + errors);
}

}  // namespace prism::gl
