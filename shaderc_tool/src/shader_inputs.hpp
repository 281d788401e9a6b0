// Stage 3 of prism-shaderc, with the contract (contract.hpp): the inputs. Turns the
// command line's files and directories into programs: the stage files that share a base
// name (`phong.vert` + `phong.frag` [+ `phong.geom`], `terrain.vert` + `.tesc` + `.tese`
// + `.frag`, or `rain.comp` alone), plus the programs `--program NAME=FILE,...` declares
// (program_declarations.hpp); a stage file that a declaration names is that program's and
// is not paired by name. A file in an input folder that is not a stage kind is a warning
// naming it, except a module (`.glsl`), which stages include. The Vulkan client also takes
// mesh programs (`x.mesh` + `x.frag` [+ `x.task`]) and ray-tracing stages (`.rgen .rint
// .rahit .rchit .rmiss .rcall`, validated each on its own); the OpenGL client refuses them.
//
//   const auto inputs = collectShaderInputs({"shaders/"}, {"blur-h=shaders/fullscreen.vert,shaders/blur.frag"});
//   sink.reportAll(inputs.diagnostics);
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "diagnostics.hpp"
#include "target_rules.hpp"

namespace prism::shaderc {

struct StageFile {
    catalog::Stage stage;
    std::string path;
};

struct ShaderInput {
    std::string name;               // base name or declared name; any text (mangleName() gives its enumerator)
    std::vector<StageFile> stages;  // in pipeline order (catalog::pipelineOrder)
};

struct ShaderInputsResult {
    std::vector<ShaderInput> shaders;  // sorted by name
    std::vector<Diagnostic> diagnostics;
    bool ioError = false;  // an input that does not exist (exit status 2, not 1)
};

// stageOfPath(), stageExtensionList(), kModuleExtension: stage_files.hpp.

// Sorts a program's stages into the order they run in (catalog::pipelineOrder).
void sortByPipelineOrder(std::vector<StageFile>& stages);

// Checks the stage kinds of one program: compute alone; ray-tracing stages alone; [task +]
// mesh + fragment; else a vertex and a fragment stage, and a tessellation control stage
// only with an evaluation stage; the fragment stage as `rules` say (needsFragmentStage: a
// Vulkan pipeline may rasterise without one). `where` is the diagnostics' file: the first
// stage file, or the --program argument.
void checkCompleteness(const ShaderInput& program, const std::string& where, std::vector<Diagnostic>& out,
                       const TargetRules& rules = {});

// Mesh, task and ray-tracing stages are taken where `rules` take them (takesVulkanOnlyStages);
// else each is an error that names the file and --client vulkan.
ShaderInputsResult collectShaderInputs(const std::vector<std::string>& inputs,
                                       const std::vector<std::string>& programDeclarations = {},
                                       const TargetRules& rules = {});

}  // namespace prism::shaderc
