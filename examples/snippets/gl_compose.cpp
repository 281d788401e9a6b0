// The usage example of prism/gl/compose.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include <cstdint>
#include <vector>

#include "prism/gl/compose.hpp"
#include "prism/shaders.hpp"  // generated catalogue: ModuleId, kCatalog
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    using prism::shaders::ModuleId;
    std::vector<prism::gl::ComposeStage> stages{
        {.stage = prism::catalog::Stage::Vertex,
         .modules = {std::uint32_t(ModuleId::transforms)},
         .source = "in vec3 a_position;\nvoid main() { gl_Position = clipPosition(eyePosition(a_position)); }\n",
         .sourceName = "my_tool/custom.vert"},
        {.stage = prism::catalog::Stage::Fragment,
         .modules = {std::uint32_t(ModuleId::material), std::uint32_t(ModuleId::fragment_output)},
         .source = "void main() { frag = u_color; }\n",
         .sourceName = "my_tool/custom.frag"},
    };
    prism::gl::Program p = prism::gl::composeProgram(prism::shaders::kCatalog, stages, "custom");
    // [/snippet]
    return p.hasUniform("u_projection") && p.hasUniform("u_color") ? 0 : 1;
}
