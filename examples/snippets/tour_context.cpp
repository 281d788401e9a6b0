// docs/runtime.md, "A headless context": create a GL context without a display and say
// what it is. Compiled and run by tests/snippets (snippets.tour_context).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"

int main() {
    // EGL on Mesa's surfaceless platform, else OSMesa: no window, no display, no GPU needed.
    std::unique_ptr<prism::gl::Context> context = prism::gl::createContext();
    const prism::gl::ContextInfo& info = context->info();
    std::cout << prism::gl::backendName(info.backend) << ": " << info.renderer << ", GL " << info.major << "."
              << info.minor << "\n";
    return info.major >= 3 ? 0 : 1;
}
// [/snippet]
