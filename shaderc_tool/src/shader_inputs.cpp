// Grouping of stage files into programs, with an error for every incomplete set and a
// warning for every file of an input folder that is not a stage.
#include "shader_inputs.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "program_declarations.hpp"
#include "stage_files.hpp"

namespace prism::shaderc {
namespace fs = std::filesystem;
namespace {

using catalog::Stage;

std::string siblingPath(const std::string& stagePath, std::string_view ext) {
    return fs::path(stagePath).replace_extension(std::string(ext)).string();
}

bool hasStage(const ShaderInput& s, Stage st) {
    return std::any_of(s.stages.begin(), s.stages.end(), [&](const StageFile& f) { return f.stage == st; });
}

// The stage files directly in `dir`, sorted; a warning for each other file but modules.
std::vector<std::string> stageFilesIn(const std::string& dir, std::vector<Diagnostic>& out) {
    std::vector<std::string> found, ignored;
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        if (stageOfPath(it->path()))
            found.push_back(it->path().string());
        else if (it->path().extension() != kModuleExtension)
            ignored.push_back(it->path().string());
    }
    std::sort(found.begin(), found.end());
    std::sort(ignored.begin(), ignored.end());
    for (const auto& f : ignored) {
        Diagnostic d = makeError(f, 0, 0,
                                 "not a stage Prism takes (" + stageExtensionList() + ") nor a module (" +
                                     std::string(kModuleExtension) + "); skipped. Move it out of the input folder");
        d.severity = Severity::Warning;
        out.push_back(std::move(d));
    }
    return found;
}

// The stage files of the positional inputs (files and folders), in order.
std::vector<std::string> stageFilesOf(const std::vector<std::string>& inputs, ShaderInputsResult& result) {
    std::vector<std::string> files;
    for (const auto& in : inputs) {
        std::error_code ec;
        if (fs::is_directory(in, ec)) {
            auto found = stageFilesIn(in, result.diagnostics);
            if (found.empty())
                result.diagnostics.push_back(makeError(in, 0, 0,
                                                       "no stage files (" + stageExtensionList() +
                                                           ") in this folder; give the folder that "
                                                           "holds them, or drop it"));
            files.insert(files.end(), found.begin(), found.end());
        } else if (!fs::exists(in, ec)) {
            result.diagnostics.push_back(makeError(in, 0, 0, "no such file or directory"));
            result.ioError = true;
        } else if (!stageOfPath(in)) {
            result.diagnostics.push_back(makeError(in, 0, 0, "unknown stage extension; use " + stageExtensionList()));
        } else {
            files.push_back(in);
        }
    }
    return files;
}

// Same-name stage files become one program each, sorted by name.
std::map<std::string, ShaderInput> pairByName(const std::vector<std::string>& files, std::vector<Diagnostic>& out) {
    std::map<std::string, ShaderInput> byName;
    for (const auto& f : files) {
        auto name = fs::path(f).stem().string();
        auto stage = *stageOfPath(f);
        auto& shader = byName[name];
        shader.name = name;
        auto dup = std::find_if(shader.stages.begin(), shader.stages.end(),
                                [&](const StageFile& s) { return s.stage == stage; });
        if (dup != shader.stages.end()) {
            if (fs::path(dup->path).lexically_normal() != fs::path(f).lexically_normal())
                out.push_back(makeError(f, 0, 0,
                                        "second " + std::string(catalog::stageName(stage)) + " stage for shader '" +
                                            name + "' (first: " + dup->path + "); shader names must be unique"));
            continue;
        }
        shader.stages.push_back({stage, f});
    }
    for (auto& [name, shader] : byName) sortByPipelineOrder(shader.stages);
    return byName;
}

}  // namespace

void sortByPipelineOrder(std::vector<StageFile>& stages) {
    std::stable_sort(stages.begin(), stages.end(), [](const StageFile& a, const StageFile& b) {
        return catalog::pipelineOrder(a.stage) < catalog::pipelineOrder(b.stage);
    });
}

namespace {

// Ray-tracing stages: validated one by one, with nothing else in their program.
void checkRayTracing(const ShaderInput& s, const std::string& where, std::vector<Diagnostic>& out) {
    if (!std::all_of(s.stages.begin(), s.stages.end(), [](const StageFile& f) { return isRayTracingStage(f.stage); }))
        out.push_back(makeError(where, 0, 0, "shader '" + s.name + "' mixes ray-tracing stages with other stages"));
}

// A program without a fragment stage: under Vulkan a pipeline may have none (a depth-only
// pass rasterises without one); under OpenGL Prism requires one, as GLSL ES 3.00 and
// WebGL 2, which a program of the OpenGL client may be emitted for, require it to link.
void checkFragmentStage(const ShaderInput& s, const std::string& where, const TargetRules& rules,
                        std::vector<Diagnostic>& out) {
    if (!rules.needsFragmentStage || hasStage(s, Stage::Fragment)) return;
    out.push_back(makeError(where, 0, 0,
                            "shader '" + s.name + "' has no fragment stage: expected " +
                                siblingPath(s.stages.front().path, ".frag") +
                                " (the OpenGL client needs one; a Vulkan pipeline, --client vulkan, does not)"));
}

// A mesh pipeline: [task +] mesh [+ frag], without vertex, geometry or compute stages.
void checkMeshPipeline(const ShaderInput& s, const std::string& where, const TargetRules& rules,
                       std::vector<Diagnostic>& out) {
    const auto& any = s.stages.front().path;
    if (hasStage(s, Stage::Vertex) || hasStage(s, Stage::Geometry) || hasStage(s, Stage::Compute) ||
        hasStage(s, Stage::TessControl) || hasStage(s, Stage::TessEvaluation))
        out.push_back(makeError(
            where, 0, 0,
            "shader '" + s.name + "' mixes a mesh pipeline with vertex, tessellation, geometry or compute stages"));
    if (!hasStage(s, Stage::Mesh))
        out.push_back(makeError(
            where, 0, 0,
            "shader '" + s.name + "' has a task stage but no mesh stage: expected " + siblingPath(any, ".mesh")));
    checkFragmentStage(s, where, rules, out);
}

}  // namespace

void checkCompleteness(const ShaderInput& s, const std::string& where, std::vector<Diagnostic>& out,
                       const TargetRules& rules) {
    const auto& any = s.stages.front().path;
    if (std::any_of(s.stages.begin(), s.stages.end(), [](const StageFile& f) { return isRayTracingStage(f.stage); }))
        return checkRayTracing(s, where, out);
    if (hasStage(s, Stage::Mesh) || hasStage(s, Stage::Task)) return checkMeshPipeline(s, where, rules, out);
    if (hasStage(s, Stage::Compute)) {
        if (s.stages.size() > 1)
            out.push_back(makeError(where, 0, 0,
                                    "shader '" + s.name +
                                        "' mixes a compute stage with graphics stages; "
                                        "make them two programs"));
        return;
    }
    if (!hasStage(s, Stage::Vertex))
        out.push_back(makeError(where, 0, 0,
                                "shader '" + s.name + "' has no vertex stage (nor a compute stage): expected " +
                                    siblingPath(any, ".vert")));
    checkFragmentStage(s, where, rules, out);
    if (hasStage(s, Stage::TessControl) && !hasStage(s, Stage::TessEvaluation))
        out.push_back(makeError(where, 0, 0,
                                "shader '" + s.name +
                                    "' has a tessellation control stage but no evaluation stage: expected " +
                                    siblingPath(any, ".tese")));
}

namespace {

// Under the OpenGL client a program with a mesh, task or ray-tracing stage is one error
// naming the file and --client vulkan (and no completeness errors): true when refused.
bool refusedVulkanOnly(const ShaderInput& s, const TargetRules& rules, std::vector<Diagnostic>& out) {
    if (rules.takesVulkanOnlyStages) return false;
    auto it = std::find_if(s.stages.begin(), s.stages.end(), [](const StageFile& f) { return isVulkanOnly(f.stage); });
    if (it == s.stages.end()) return false;
    out.push_back(makeError(it->path, 0, 0,
                            "a ." + std::string(catalog::stageName(it->stage)) +
                                " stage is Vulkan GLSL: build it with --client vulkan "
                                "(prism_add_shaders(... CLIENT vulkan))"));
    return true;
}

}  // namespace

ShaderInputsResult collectShaderInputs(const std::vector<std::string>& inputs,
                                       const std::vector<std::string>& programDeclarations, const TargetRules& rules) {
    ShaderInputsResult result;
    const DiskReader disk;
    auto files = stageFilesOf(inputs, result);
    const auto declaredFiles = filesNamedBy(programDeclarations, disk);
    std::erase_if(files, [&](const std::string& f) {
        const auto canonical = disk.canonical(f);
        return canonical && declaredFiles.contains(*canonical);
    });
    auto byName = pairByName(files, result.diagnostics);
    for (auto& [name, shader] : byName) {
        if (refusedVulkanOnly(shader, rules, result.diagnostics)) continue;
        checkCompleteness(shader, shader.stages.front().path, result.diagnostics, rules);
        result.shaders.push_back(std::move(shader));
    }
    auto declared = declaredPrograms(programDeclarations, result.shaders, disk, rules);
    result.diagnostics.insert(result.diagnostics.end(), declared.diagnostics.begin(), declared.diagnostics.end());
    result.ioError = result.ioError || declared.ioError;
    for (auto& p : declared.programs)
        if (!refusedVulkanOnly(p, rules, result.diagnostics)) result.shaders.push_back(std::move(p));
    std::sort(result.shaders.begin(), result.shaders.end(),
              [](const ShaderInput& a, const ShaderInput& b) { return a.name < b.name; });
    return result;
}

}  // namespace prism::shaderc
