// docs/runtime.md, "Composition at run time": a program from catalogue modules plus your own
// GLSL, with no shader file and no build step. Compiled and run by tests/snippets
// (snippets.tour_compose).
// [snippet]
#include <cstdint>
#include <iostream>
#include <vector>

#include "prism/gl/compose.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/shaders.hpp"

using prism::shaders::ModuleId;

int main() {
    auto context = prism::gl::createContext();

    // Your main() functions; the modules provide the uniforms and functions they call:
    // transforms.glsl eyePosition() and clipPosition(), normals.glsl eyeNormal(),
    // lighting.glsl shade() (with lights.glsl, material.glsl, specular.glsl pulled in).
    std::vector<prism::gl::ComposeStage> stages{
        {.stage = prism::catalog::Stage::Vertex,
         .modules = {std::uint32_t(ModuleId::transforms), std::uint32_t(ModuleId::normals)},
         .source = "in vec3 a_position;\n"
                   "in vec3 a_normal;\n"
                   "out vec3 v_eyePos;\n"
                   "out vec3 v_normal;\n"
                   "void main() {\n"
                   "    vec4 eye = eyePosition(a_position);\n"
                   "    v_eyePos = eye.xyz;\n"
                   "    v_normal = eyeNormal(a_normal);\n"
                   "    gl_Position = clipPosition(eye);\n"
                   "}\n",
         .sourceName = "my_tool/lit.vert"},
        {.stage = prism::catalog::Stage::Fragment,
         .modules = {std::uint32_t(ModuleId::lighting), std::uint32_t(ModuleId::fragment_output)},
         .source = "in vec3 v_eyePos;\n"
                   "in vec3 v_normal;\n"
                   "void main() { frag = vec4(shade(v_eyePos, normalize(v_normal), true), u_color.a); }\n",
         .sourceName = "my_tool/lit.frag"},
    };
    // Modules come in dependency order, each once; #line directives keep every error at
    // its own file and line (a typo in lit.frag reports my_tool/lit.frag:3:...).
    for (std::uint32_t m : prism::gl::moduleOrder(prism::shaders::kCatalog, stages[1].modules))
        std::cout << prism::shaders::name(static_cast<ModuleId>(m)) << " ";
    std::cout << "\n";
    prism::gl::Program program = prism::gl::composeProgram(prism::shaders::kCatalog, stages, "lit");
    return program.hasUniform("u_lightDirection") ? 0 : 1;
}
// [/snippet]
