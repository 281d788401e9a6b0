// The usage example of prism/render/program_cache.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/render/program_cache.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::gl::Program& p = cache.get("phong", {{"BLINN", "1"}});
    cache.size();   // programs built so far
    // [/snippet]
    return &p == &cache.get("phong", {{"BLINN", "1"}}) && cache.size() == 1 ? 0 : 1;
}
