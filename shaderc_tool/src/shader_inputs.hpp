// Stage 3 of prism-shaderc, with the contract (contract.hpp): the inputs. Turns the
// command line's files and directories into shaders: the stage files that
// share a base name (`phong.vert` + `phong.frag` [+ `phong.geom`], or `rain.comp` alone).
// The Vulkan client also takes mesh programs (`x.mesh` + `x.frag` [+ `x.task`]) and
// ray-tracing stages (`.rgen .rint .rahit .rchit .rmiss .rcall`, each validated on its own).
//
//   auto inputs = collectShaderInputs({"shaders/"}, /*vulkanClient=*/false);
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "diagnostics.hpp"

namespace prism::shaderc {

struct StageFile {
    catalog::Stage stage;
    std::string path;
};

struct ShaderInput {
    std::string name;               // base name, a C++ identifier
    std::vector<StageFile> stages;  // in pipeline order
};

struct ShaderInputsResult {
    std::vector<ShaderInput> shaders;  // sorted by name
    std::vector<Diagnostic> diagnostics;
    bool ioError = false;  // an input that does not exist (exit status 2, not 1)
};

// The stage kind a file's extension names (".vert" ... ".rcall"), whatever the client.
std::optional<catalog::Stage> stageOfPath(const std::filesystem::path& path);

// `vulkanClient`: mesh, task and ray-tracing stages are taken; else each is an error that
// names the file and --client vulkan.
ShaderInputsResult collectShaderInputs(const std::vector<std::string>& inputs, bool vulkanClient = false);

}  // namespace prism::shaderc
