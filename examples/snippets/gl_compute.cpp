// The usage example of prism/gl/compute.hpp, compiled and run by tests/snippets.
#include <cstdint>
#include <utility>

#include "prism/gl/program.hpp"
// [snippet]
#include "prism/gl/compute.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    prism::gl::requireCompute("my effect");               // throws ComputeUnavailableError on GL < 4.3
    auto groups = prism::gl::computeGroups(100000, 256);  // {391, 1}
    // [/snippet]
    prism::gl::ProgramSources sources{.label = "empty compute",
                                      .stages = {{.stage = prism::catalog::Stage::Compute,
                                                  .source = "#version 430 core\n"
                                                            "layout(local_size_x = 256) in;\n"
                                                            "void main() {}\n",
                                                  .files = {}}},
                                      .attributes = {},
                                      .uniforms = std::nullopt};
    prism::gl::Program program(std::move(sources));
    program.use();
    // [snippet]
    // with a compute program in use and its buffers bound:
    std::uint64_t before = prism::gl::computeDispatches();
    prism::gl::dispatchInvocations(100000, 256);                  // glDispatchCompute(391, 1, 1)
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);               // barriers: the loader's own bits
    std::uint64_t ran = prism::gl::computeDispatches() - before;  // 1
    // [/snippet]
    prism::gl::throwIfGlError("the dispatch");
    return groups[0] == 391 && groups[1] == 1 && ran == 1 ? 0 : 1;
}
