// The build step's stages as a library, for the runtime (composition, module libraries,
// hot reload) and the prism-shaderc tool alike: one include resolver, one binding
// contract, one glslang validation and one module naming, so a shader means the same at
// build time and at run time (Filament's matc and filamat split). Every diagnostic is one
// GCC-style text, `path:line:col: error: message` plus its "included from" lines.
//
// Usage (snippet: examples/snippets/shaderc_build_step.cpp):
//
//     #include "prism/shaderc/build_step.hpp"
//     namespace sc = prism::shaderc;
//     const std::pair<std::string, std::string> files[] = {
//         {"shaders/tint.frag", "#include \"lib/tint.glsl\"\nout vec4 frag;\nvoid main() { frag = tint(); }\n"},
//         {"shaders/lib/tint.glsl", "vec4 tint() { return vec4(1.0, 0.5, 0.5, 1.0); }\n"}};
//     const sc::Files memory = sc::Files::memory(files);
//     const sc::StageResolution stage = sc::resolveStage("shaders/tint.frag", {}, memory);
//     // stage.ok; stage.resolved.files: shaders/tint.frag, shaders/lib/tint.glsl
//     // sc::moduleId("lib/tint.glsl") == "lib__tint"
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"

namespace prism::shaderc {

// Where the stages read files: the file system, or in-memory (path, text) pairs.
class Files {
  public:
    static Files disk();  // reads each file once per Files object: make a new one to see edits
    static Files memory(std::span<const std::pair<std::string, std::string>> files);
    Files(Files&&) noexcept;
    Files& operator=(Files&&) noexcept;
    ~Files();

    struct Impl;  // the tool's SourceReader
    const Impl& impl() const { return *impl_; }

  private:
    explicit Files(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// One problem found by a stage, formatted as the tool prints it.
struct Message {
    bool error = true;  // else a warning or note
    std::string text;   // `path:line:col: error: message` (+ "included from" lines), ends with '\n'
};

bool hasError(std::span<const Message> messages);
// An error of the build step's form, for problems found outside its stages.
Message errorAt(const std::string& file, int line, int column, const std::string& message);

// The binding contract (contract.json files): attributes with locations, uniforms with
// their largest array size (0: not an array). `files` name it in diagnostics.
struct ContractName {
    std::string name;
    std::string type;          // GLSL type name
    std::uint32_t glType = 0;  // its GL enum
    int location = 0;          // attributes
    int array = 0;             // uniforms
};
struct BindingContract {
    std::vector<std::string> files;
    std::vector<ContractName> attributes;
    std::vector<ContractName> uniforms;
    bool builtIn = false;  // Prism's own, loaded from no paths: a near miss is then a warning
};
struct ContractLoad {
    BindingContract contract;
    std::vector<Message> messages;
    bool ok = false;  // readable and no errors
};
ContractLoad loadContract(std::span<const std::string> paths, const Files& files);
// GL enum of a GLSL type name (GL_FLOAT_VEC3 ...), 0 when unknown.
std::uint32_t glTypeOf(const std::string& glslType);

// The -I, -D and default #version of a resolution, as prism-shaderc's options.
struct ResolveSettings {
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;
    std::string defaultVersion = "#version 330 core";
    std::string baseDir;
};

// A stage flattened with its #includes (dependencies once, `#line` per file) and its
// first #version kept; `files[n]` is the path of source number n.
struct FlatStage {
    std::string text;
    std::vector<std::string> files;
    std::vector<std::string> filesRead;  // every file read, in order
    // The resolver's own record (each file's "included from" chain) when resolveStage made
    // this stage; without it (a text composed elsewhere) errors carry no include chain.
    struct Record;
    std::shared_ptr<const Record> record;
};
struct StageResolution {
    bool ok = false;
    FlatStage resolved;
    std::vector<Message> messages;
};
StageResolution resolveStage(const std::string& path, const ResolveSettings& settings, const Files& files);

// A module as the catalogue stores it (includes and #pragma once blanked, #version kept) and the
// files its active #includes name, in order.
struct ModuleText {
    std::string path, canonical, text, description;
    std::vector<std::string> includes;
};
struct ModuleScan {
    bool ok = false;
    ModuleText module;
    std::vector<Message> messages;
};
ModuleScan scanModule(const std::string& path, const ResolveSettings& settings, const Files& files);
// The canonical identity of a file, "" when it does not exist.
std::string canonicalPath(const std::string& path, const Files& files);

// The catalogue's module identifier of a path relative to its root (the -I directory
// that found it): "toon/quantize.glsl" -> "toon__quantize".
std::string moduleId(std::string_view relativePath);

// glslang's process state, held while an object lives (counted: safe beside other users).
class Validator {
  public:
    Validator();
    ~Validator();
    Validator(const Validator&) = delete;
    Validator& operator=(const Validator&) = delete;
};

struct StageToCheck {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::string path;  // for errors without a line
    FlatStage resolved;
};
struct UniformFound {
    std::string name;
    std::uint32_t glType = 0;
    int arraySize = 1;
};
struct ProgramCheck {
    bool ok = false;
    std::vector<UniformFound> uniforms;  // sorted by name
    std::vector<Message> messages;
};
// glslang compile and link of every stage, the cross-stage interface check and the
// contract check; needs a live Validator.
ProgramCheck checkProgram(std::span<const StageToCheck> stages, const BindingContract& contract);

}  // namespace prism::shaderc
