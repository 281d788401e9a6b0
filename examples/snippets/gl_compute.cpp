// The usage example of prism/gl/compute.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/gl/compute.hpp"
#include "prism/gl/gl_context.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    prism::gl::requireCompute("my effect");            // throws ComputeUnavailableError on GL < 4.3
    auto groups = prism::gl::computeGroups(100000, 256);  // {391, 1}
    // bind a program and buffers, then: prism::gl::dispatchInvocations(100000, 256);
    // [/snippet]
    return groups[0] == 391 && groups[1] == 1 ? 0 : 1;
}
