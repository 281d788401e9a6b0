// A module library read at run time, for composing programs without a generated
// catalogue: GLSL module files (or strings) and binding-contract JSON, read by the shader
// tool's own stages (prism_shaderc_lib), so includes, descriptions and contract errors work
// exactly as in the build step. catalog() can be passed to composeProgram().
//
// Usage (snippet: examples/snippets/gl_module_library.cpp):
//
//     #include "prism/gl/compose.hpp"
//     #include "prism/gl/module_library.hpp"
//     auto library = prism::gl::ModuleLibrary::fromStrings(
//         {{"lib/tint.glsl", "vec3 tint(vec3 c) { return c * vec3(1.0, 0.5, 0.5); }\n"}},
//         R"({"attributes": [{"name": "a_position", "type": "vec2", "location": 0}], "uniforms": []})");
//     std::vector<prism::gl::ComposeStage> stages{
//         {.stage = prism::catalog::Stage::Vertex,
//          .modules = {},
//          .source = "in vec2 a_position;\nvoid main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n",
//          .sourceName = "app/tinted.vert"},
//         {.stage = prism::catalog::Stage::Fragment,
//          .modules = {library.id("tint")},
//          .source = "out vec4 frag;\nvoid main() { frag = vec4(tint(vec3(1.0)), 1.0); }\n",
//          .sourceName = "app/tinted.frag"}};
//     prism::gl::Program program = prism::gl::composeProgram(library, stages, "tinted");
//
// Module ids are the build step's (prism::shaderc::moduleId): the path under the first
// include directory holding it, mangled ("modules/toon/quantize.glsl" under "modules" is
// "toon__quantize"); without include directories each file's own folder is its root
// ("lib/tint.glsl" is "tint"), and two files with one id are an error naming both. A
// module may #include another module of the library, found in the build step's search
// order. Errors (unreadable file, missing include, an unguarded include cycle, bad
// contract JSON) throw CompositionError with `path:line:col: error: ...` diagnostics.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"

namespace prism::gl {

class ModuleLibrary {
  public:
    // Module files on disk and contract files; `includeDirs` are prism-shaderc's -I (the
    // roots of module ids), by default each module's own folder.
    static ModuleLibrary fromFiles(std::span<const std::string> moduleFiles, std::span<const std::string> contractFiles,
                                   std::string versionDirective = "#version 330 core",
                                   std::span<const std::string> includeDirs = {});
    // Modules as (path, text) pairs and one contract as JSON text.
    static ModuleLibrary fromStrings(std::span<const std::pair<std::string, std::string>> modules,
                                     std::string_view contractJson, std::string versionDirective = "#version 330 core",
                                     std::span<const std::string> includeDirs = {});
    static ModuleLibrary fromStrings(std::initializer_list<std::pair<std::string, std::string>> modules,
                                     std::string_view contractJson, std::string versionDirective = "#version 330 core",
                                     std::span<const std::string> includeDirs = {}) {
        return fromStrings(std::span<const std::pair<std::string, std::string>>(modules.begin(), modules.size()),
                           contractJson, std::move(versionDirective), includeDirs);
    }

    ModuleLibrary(ModuleLibrary&&) noexcept;
    ModuleLibrary& operator=(ModuleLibrary&&) noexcept;
    ~ModuleLibrary();

    // A catalogue view (no shaders) of the modules and contract; valid while this object lives.
    const catalog::Catalog& catalog() const;
    // The contract's files, which composition's contract errors name.
    std::span<const std::string> contractFiles() const;
    // The id of a module by name; throws CompositionError listing the names (with "did you mean").
    std::uint32_t id(std::string_view name) const;

    struct Storage;  // opaque: owns every string and table the catalogue view points into

  private:
    explicit ModuleLibrary(std::unique_ptr<Storage> storage);
    std::unique_ptr<Storage> storage_;
};

}  // namespace prism::gl
