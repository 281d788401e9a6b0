// The usage example of prism/rain/compute.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/program.hpp"
#include "prism/rain/gl_resources.hpp"
// [snippet]
#include "prism/rain/compute.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    const std::uint32_t count = 1000;
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
    prism::rain::ComputeFunctions compute = prism::rain::loadComputeFunctions();  // throws if unavailable
    // with a compute program in use and its buffers bound:
    compute.dispatch(count);        // ceil(count / 256) groups of 256, split over x and y
    compute.barrier(prism::rain::kBarrierAll);
    // [/snippet]
    prism::gl::throwIfGlError("the dispatch");
    return prism::rain::glObjectCounts().computeDispatches == 1 ? 0 : 1;
}
