// The compute entry points the water system uses, from prism_gl's GL 4.5 loader. Internal.
#pragma once

#include "prism/gl/compute.hpp"
#include "prism/gl/gl.hpp"

namespace prism::water::detail {

inline constexpr GLenum kShaderStorageBuffer = 0x90D2;       // GL_SHADER_STORAGE_BUFFER
inline constexpr GLbitfield kShaderStorageBarrier = 0x2000;  // GL_SHADER_STORAGE_BARRIER_BIT
inline constexpr GLbitfield kAllBarriers = 0xFFFFFFFFu;      // GL_ALL_BARRIER_BITS

struct ComputeFunctions {
    void (*dispatchCompute)(GLuint, GLuint, GLuint) = nullptr;
    void (*memoryBarrier)(GLbitfield) = nullptr;
};

// The loader's glDispatchCompute/glMemoryBarrier; throws gl::ComputeUnavailableError
// when the current context is older than GL 4.3.
inline ComputeFunctions loadComputeFunctions() {
    gl::requireCompute("prism water: the GPU simulation (or use the CPU simulation)");
    return {glad_glDispatchCompute, glad_glMemoryBarrier};
}

inline int currentGlVersion() {
    return gl::currentContextVersion();
}

}  // namespace prism::water::detail
