// The GL 4.3 compute entry points the project's GL 3.3 loader (glad, runtime/gl) does
// not load: glDispatchCompute and glMemoryBarrier, looked up through the current
// context's own get-proc-address function (EGL, OSMesa or GLFW).
//
//     prism::rain::ComputeFunctions gl43 = prism::rain::loadComputeFunctions();  // throws if unavailable
//     gl43.dispatch(count);        // ceil(count / 256) groups of 256, split over x and y
//     gl43.barrier(prism::rain::kBarrierAll);
//
// Create the context with ContextOptions{.majorVersion = 4, .minorVersion = 3} (Mesa's
// llvmpipe gives 4.5 core).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>

namespace prism::rain {

class ComputeUnavailableError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

inline constexpr unsigned kShaderStorageBuffer = 0x90D2;           // GL_SHADER_STORAGE_BUFFER
inline constexpr unsigned kBarrierVertexAttribArray = 0x00000001;  // GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT
inline constexpr unsigned kBarrierBufferUpdate = 0x00000200;       // GL_BUFFER_UPDATE_BARRIER_BIT
inline constexpr unsigned kBarrierShaderStorage = 0x00002000;      // GL_SHADER_STORAGE_BARRIER_BIT
inline constexpr unsigned kBarrierAll = kBarrierVertexAttribArray | kBarrierBufferUpdate | kBarrierShaderStorage;
inline constexpr std::uint32_t kComputeGroupSize = 256;  // local_size_x of the rain .comp shaders

// Work groups for `count` invocations: x <= 65535, y as needed (0 groups for count 0).
std::array<std::uint32_t, 2> computeGroups(std::uint32_t count, std::uint32_t groupSize = kComputeGroupSize);

struct ComputeFunctions {
    void (*dispatchCompute)(unsigned x, unsigned y, unsigned z) = nullptr;
    void (*memoryBarrier)(unsigned bits) = nullptr;

    void dispatch(std::uint32_t count) const;
    void barrier(unsigned bits) const { memoryBarrier(bits); }
};

// Whether the current context is GL >= 4.3 with the two functions found.
bool computeAvailable();
// Throws ComputeUnavailableError saying what is missing.
ComputeFunctions loadComputeFunctions();

}  // namespace prism::rain
