// GL 4.3 entry points the water system needs beyond the project's GL 3.3 loader
// (glDispatchCompute, glMemoryBarrier), fetched through the get-proc-address function
// of whichever context backend is current (OSMesa, EGL or GLFW). Internal.
#pragma once

#include "prism/gl.hpp"

namespace prism::water::detail {

inline constexpr GLenum kShaderStorageBuffer = 0x90D2;       // GL_SHADER_STORAGE_BUFFER
inline constexpr GLbitfield kShaderStorageBarrier = 0x2000;  // GL_SHADER_STORAGE_BARRIER_BIT
inline constexpr GLbitfield kAllBarriers = 0xFFFFFFFFu;      // GL_ALL_BARRIER_BITS

struct ComputeFunctions {
    void (*dispatchCompute)(GLuint, GLuint, GLuint) = nullptr;
    void (*memoryBarrier)(GLbitfield) = nullptr;
};

// Loads them for the current context; throws prism::gl::ContextError when the context
// is older than GL 4.3 or the functions cannot be found.
ComputeFunctions loadComputeFunctions();

// GL_MAJOR_VERSION.GL_MINOR_VERSION of the current context as 10 * major + minor.
int currentGlVersion();

}  // namespace prism::water::detail
