// Compute shaders (GL 4.3): whether the current context has them, and dispatching a
// one-dimensional range of invocations. The loader (prism_glad, GL 4.5 core) loads the
// entry points once for every context; on an older context they stay null.
//
// Usage (snippet: examples/snippets/gl_compute.cpp):
//
//     #include "prism/gl/compute.hpp"
//     #include "prism/gl/gl_context.hpp"
//     auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
//     prism::gl::requireCompute("my effect");            // throws ComputeUnavailableError on GL < 4.3
//     auto groups = prism::gl::computeGroups(100000, 256);  // {391, 1}
//     // bind a program and buffers, then: prism::gl::dispatchInvocations(100000, 256);
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

}  // namespace prism::gl
