// The usage example of prism/render/program_cache.hpp, compiled and run by tests/snippets.
#include <utility>

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
    cache.size();  // programs built so far

    // Hot reload (prism/render/shader_watcher.hpp does this on a file edit): swap in a
    // program rebuilt from edited sources. References from get() stay valid and name
    // the new program from now on.
    const prism::catalog::Variant& blinn = cache.variantOf("phong", {{"BLINN", "1"}});
    prism::gl::Program rebuilt(blinn, prism::shaders::kCatalog.contractAttributes, "phong");
    cache.reload("phong", blinn.name, std::move(rebuilt));
    // [/snippet]
    return &p == &cache.get("phong", {{"BLINN", "1"}}) && cache.size() == 1 ? 0 : 1;
}
