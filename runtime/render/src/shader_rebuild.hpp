// In-process rebuild of one catalogue variant from its source files, through the shader
// tool's own library (prism_shaderc_lib): the include resolver reading from disk, the
// contract, glslang validation with the cross-stage interface and contract checks, and
// reflection, as prism-shaderc's main() sequences them. No process is spawned. Used by
// ShaderWatcher (hot reload); private to prism_render.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/gl/program.hpp"

namespace prism::render::detail {

struct StageFilePath {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::string path;  // the stage file on disk
};

struct RebuildRequest {
    std::string label;                                         // names the program
    std::vector<StageFilePath> stages;                         // in pipeline order
    std::vector<std::pair<std::string, std::string>> defines;  // the variant's axis values
    std::vector<std::string> includeDirs;                      // prism-shaderc's -I
    std::string versionDirective;                              // the catalogue's default #version
};

struct RebuildOutcome {
    // The validated sources with reflection, ready for gl::Program; empty on any error.
    std::optional<gl::ProgramSources> sources;
    std::vector<std::string> diagnostics;  // GCC style `path:line:col: error: ...`, one text each
    std::vector<std::string> filesRead;    // every file the resolver read (paths as joined)
};

// Owns the binding contract and glslang's process state for its lifetime.
class ShaderRebuilder {
  public:
    explicit ShaderRebuilder(std::vector<std::string> contractFiles);
    ~ShaderRebuilder();
    ShaderRebuilder(const ShaderRebuilder&) = delete;
    ShaderRebuilder& operator=(const ShaderRebuilder&) = delete;

    // (Re)reads the contract files; on error keeps the previous contract and returns
    // the diagnostics (empty on success).
    std::vector<std::string> loadContract();
    const std::vector<std::string>& contractFiles() const { return contractFiles_; }

    // Resolves and validates every stage; thread-compatible (one call at a time).
    RebuildOutcome rebuild(const RebuildRequest& request) const;

  private:
    struct State;
    std::vector<std::string> contractFiles_;
    std::unique_ptr<State> state_;
};

}  // namespace prism::render::detail
