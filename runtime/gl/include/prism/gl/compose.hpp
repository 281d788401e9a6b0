// Run-time composition of programs from catalogue modules plus your own GLSL: the
// `SHADER_MODULE.LIGHTS + ...` idea of the FUDGE shader thesis (§7.1), with dependencies pulled in once, in order,
// and driver errors mapped back to each module's file and line.
//
// Usage (snippet: examples/snippets/gl_compose.cpp):
//
//     #include <cstdint>
//     #include <vector>
//
//     #include "prism/gl/compose.hpp"
//     #include "prism/shaders.hpp"  // generated catalogue: ModuleId, kCatalog
//     using prism::shaders::ModuleId;
//     std::vector<prism::gl::ComposeStage> stages{
//         {.stage = prism::catalog::Stage::Vertex,
//          .modules = {std::uint32_t(ModuleId::transforms)},
//          .source = "in vec3 a_position;\nvoid main() { gl_Position = clipPosition(eyePosition(a_position)); }\n",
//          .sourceName = "my_tool/custom.vert"},
//         {.stage = prism::catalog::Stage::Fragment,
//          .modules = {std::uint32_t(ModuleId::material), std::uint32_t(ModuleId::fragment_output)},
//          .source = "void main() { frag = u_color; }\n",
//          .sourceName = "my_tool/custom.frag"},
//     };
//     prism::gl::Program p = prism::gl::composeProgram(prism::shaders::kCatalog, stages, "custom");
//
// Each stage's source is laid out as
//
//     #version 330 core          <- your source's #version, else the catalogue's versionDirective
//     #define NAME VALUE         <- the optional defines, in order
//     #line 1 1                  <- module 1 (dependencies first), its text from line 1
//     ...
//     #line 1 0                  <- your source, from line 1
//
// so the driver's `N:L(C)` positions are real file lines (for #version 330 and later
// `#line L N` names the NEXT line; older versions get `#line L-1 N`). Source number 0
// is your code, 1..k the modules; the files table maps them to paths for errors.
// Modules come in dependency order (dependencies before dependants, otherwise in the
// order asked for); each module appears once however often it is reached (diamonds).
// Your source is resolved as the build step resolves a stage (prism/shaderc/build_step.hpp):
// its first `#version` line replaces the catalogue's, and each active `#include` is found
// in the build step's search order (your file's folder, then the modules' roots) and must
// be a module of the catalogue, which then joins `modules`; both lines are blanked (line
// numbers kept). A missing include, an include cycle, or an included module whose
// `#version` differs from yours (`#version 330 core conflicts with #version 450 core at
// ...`) throws CompositionError with the build step's `path:line:col: error: ...`
// diagnostic, as do unknown module ids and dependency cycles. Given the catalogue's source
// tree, the modules are named where the build step read them (tree's base dir or -I dir).
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "prism/gl/program.hpp"
#include "prism/catalog/shader_catalog.hpp"
#include "prism/catalog/source_tree.hpp"

namespace prism::gl {

class ModuleLibrary;

// A composition problem. `diagnostics` holds one GCC-style line per problem found by the
// build step's checks (`path:line:col: error: message`), empty for errors found before them.
class CompositionError : public std::runtime_error {
  public:
    explicit CompositionError(const std::string& message, std::vector<std::string> diagnostics = {})
        : std::runtime_error(message), diagnostics(std::move(diagnostics)) {}
    std::vector<std::string> diagnostics;
};

struct ComposeStage {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::vector<std::uint32_t> modules;  // ModuleId values wanted directly
    std::string source;                  // your GLSL for this stage; #version and #include as in a stage file
    std::string sourceName;              // its path in error messages; default "<composed vert>"
};

// Every module needed for `wanted`, dependencies first, each once; stable otherwise.
std::vector<std::uint32_t> moduleOrder(const catalog::Catalog& catalog, std::span<const std::uint32_t> wanted);

// One stage's full source and files table.
StageText composeStage(const catalog::Catalog& catalog, const ComposeStage& stage,
                       std::span<const catalog::Define> defines = {});

// All stages, plus the catalogue's contract attributes; uniforms are taken from the
// driver when the Program links (there is no reflection for composed code).
ProgramSources composeSources(const catalog::Catalog& catalog, std::span<const ComposeStage> stages,
                              std::string label = "composed", std::span<const catalog::Define> defines = {});

// Composes, then runs the same checks as prism-shaderc's build step (glslang compile and
// link, cross-stage interfaces, the contract of `catalog`: an unknown `a_`/`u_` name is an
// error with "did you mean"); throws CompositionError listing every diagnostic, at each
// module's own file:line. Then links with the driver (ShaderBuildError on failure).
Program composeProgram(const catalog::Catalog& catalog, std::span<const ComposeStage> stages,
                       std::string label = "composed", std::span<const catalog::Define> defines = {});
// The same for a generated catalogue with the source tree prism_add_shaders() recorded
// beside it (`<ns>::kSourceTree`): its contract errors name the tree's contract files.
Program composeProgram(const catalog::Catalog& catalog, const catalog::SourceTree& tree,
                       std::span<const ComposeStage> stages, std::string label = "composed",
                       std::span<const catalog::Define> defines = {});
// The same for a library read at run time: its contract errors name its contract files.
Program composeProgram(const ModuleLibrary& library, std::span<const ComposeStage> stages,
                       std::string label = "composed", std::span<const catalog::Define> defines = {});

}  // namespace prism::gl
