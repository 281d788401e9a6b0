// Shared by the stages of prism-shaderc (stage 0): which files are stages, by extension,
// and which are modules. The inputs (shader_inputs.hpp) group them; the run record
// (source_fingerprint.hpp, code_signature.hpp) lists an input folder's stage files.
//
//   stageOfPath("shaders/blur.frag")   -> catalog::Stage::Fragment
//   stageOfPath("shaders/notes.txt")   -> nullopt
//   stageExtensionList()               -> ".vert, .tesc, ... or .comp (with --client vulkan also .mesh, ...)"
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <prism/catalog/shader_catalog.hpp>

namespace prism::shaderc {

// The stage kind a file's extension names (".vert" ... ".rcall", whatever the client),
// nullopt for any other file.
std::optional<catalog::Stage> stageOfPath(const std::filesystem::path& path);

// The extensions stageOfPath() knows, for messages: ".vert, .tesc, ... or .comp (with
// --client vulkan also .mesh, ...)".
std::string stageExtensionList();

// True for the stages only a Vulkan client takes (mesh, task and the ray-tracing stages).
bool isVulkanOnly(catalog::Stage stage);

// The extension of a module file: in an input folder it is no stage and no warning.
inline constexpr std::string_view kModuleExtension = ".glsl";

}  // namespace prism::shaderc
