// Compute shaders (GL 4.3): whether the current context has them, and dispatches, counted
// process-wide so a test can show that a feature ran none. The one compute wrapper of
// Prism (rain and water use it). The loader (prism_glad, GL 4.5 core) loads the entry
// points once for every context; on an older context they stay null. Memory barriers
// are plain glMemoryBarrier calls with the loader's GL_*_BARRIER_BIT values.
//
// Usage (snippet: examples/snippets/gl_compute.cpp):
//
//     #include "prism/gl/compute.hpp"
//     #include "prism/gl/gl.hpp"
//     #include "prism/gl/gl_context.hpp"
//     auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
//     prism::gl::requireCompute("my effect");               // throws ComputeUnavailableError on GL < 4.3
//     auto groups = prism::gl::computeGroups(100000, 256);  // {391, 1}
//     // with a compute program in use and its buffers bound:
//     std::uint64_t before = prism::gl::computeDispatches();
//     prism::gl::dispatchInvocations(100000, 256);                  // glDispatchCompute(391, 1, 1)
//     glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);               // barriers: the loader's own bits
//     std::uint64_t ran = prism::gl::computeDispatches() - before;  // 1
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string_view>

namespace prism::gl {

class ComputeUnavailableError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// 10 * major + minor of the current context (e.g. 45).
int currentContextVersion();

// Whether the current context is GL >= 4.3 and glDispatchCompute/glMemoryBarrier are loaded.
bool computeAvailable();

// Throws ComputeUnavailableError naming `who`, the context's version and what to do.
void requireCompute(std::string_view who);

// Work groups for `count` invocations of `groupSize`: x <= 65535, y as needed; {0, 0} for 0.
std::array<std::uint32_t, 2> computeGroups(std::uint32_t count, std::uint32_t groupSize);

// glDispatchCompute over computeGroups(count, groupSize) (nothing for count 0). The
// shader maps gl_WorkGroupID.y * gl_NumWorkGroups.x + x back to a linear index.
void dispatchInvocations(std::uint32_t count, std::uint32_t groupSize);

// glDispatchCompute(x, y, z) of work groups sized by the shader (nothing when one is 0).
void dispatchGroups(std::uint32_t x, std::uint32_t y = 1, std::uint32_t z = 1);

// Dispatches made by dispatchInvocations and dispatchGroups since start-up, all threads.
std::uint64_t computeDispatches();

}  // namespace prism::gl
