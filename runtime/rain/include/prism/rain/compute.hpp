// The rain system's compute dispatches, counted for tests, on top of prism/gl/compute.hpp
// (the GL 4.5 loader of prism_gl provides glDispatchCompute; nothing is looked up here).
//
// Usage (snippet: examples/snippets/rain_compute.cpp):
//
//     #include "prism/rain/compute.hpp"
//     prism::rain::ComputeFunctions compute = prism::rain::loadComputeFunctions();  // throws if unavailable
//     // with a compute program in use and its buffers bound:
//     compute.dispatch(count);        // ceil(count / 256) groups of 256, split over x and y
//     compute.barrier(prism::rain::kBarrierAll);
//
// Create the context with ContextOptions{.majorVersion = 4, .minorVersion = 3} (Mesa's
// llvmpipe gives 4.5 core).
#pragma once

#include <array>
#include <cstdint>

#include "prism/gl/compute.hpp"

namespace prism::rain {

using ComputeUnavailableError = gl::ComputeUnavailableError;

inline constexpr unsigned kShaderStorageBuffer = 0x90D2;           // GL_SHADER_STORAGE_BUFFER
inline constexpr unsigned kBarrierVertexAttribArray = 0x00000001;  // GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT
inline constexpr unsigned kBarrierBufferUpdate = 0x00000200;       // GL_BUFFER_UPDATE_BARRIER_BIT
inline constexpr unsigned kBarrierShaderStorage = 0x00002000;      // GL_SHADER_STORAGE_BARRIER_BIT
inline constexpr unsigned kBarrierAll = kBarrierVertexAttribArray | kBarrierBufferUpdate | kBarrierShaderStorage;
inline constexpr std::uint32_t kComputeGroupSize = 256;  // local_size_x of the rain .comp shaders

// Work groups for `count` invocations: x <= 65535, y as needed (0 groups for count 0).
inline std::array<std::uint32_t, 2> computeGroups(std::uint32_t count, std::uint32_t groupSize = kComputeGroupSize) {
    return gl::computeGroups(count, groupSize);
}

struct ComputeFunctions {
    void dispatch(std::uint32_t count) const;  // counted in glObjectCounts().computeDispatches
    void barrier(unsigned bits) const;
};

// Whether the current context is GL >= 4.3 with compute loaded.
bool computeAvailable();
// Throws ComputeUnavailableError saying what is missing.
ComputeFunctions loadComputeFunctions();

}  // namespace prism::rain
