// The usage example of prism/gl/module_library.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/gl/compose.hpp"
#include "prism/gl/module_library.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    auto library = prism::gl::ModuleLibrary::fromStrings(
        {{"lib/tint.glsl", "vec3 tint(vec3 c) { return c * vec3(1.0, 0.5, 0.5); }\n"}},
        R"({"attributes": [{"name": "a_position", "type": "vec2", "location": 0}], "uniforms": []})");
    std::vector<prism::gl::ComposeStage> stages{
        {.stage = prism::catalog::Stage::Vertex,
         .modules = {},
         .source = "in vec2 a_position;\nvoid main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n",
         .sourceName = "app/tinted.vert"},
        {.stage = prism::catalog::Stage::Fragment,
         .modules = {library.id("tint")},
         .source = "out vec4 frag;\nvoid main() { frag = vec4(tint(vec3(1.0)), 1.0); }\n",
         .sourceName = "app/tinted.frag"}};
    prism::gl::Program program = prism::gl::composeProgram(library, stages, "tinted");
    // [/snippet]
    return program.id() != 0 ? 0 : 1;
}
