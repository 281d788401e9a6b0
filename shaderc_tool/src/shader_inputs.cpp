// Grouping of stage files into shaders, with an error for every incomplete set.
#include "shader_inputs.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

namespace prism::shaderc {
namespace fs = std::filesystem;
namespace {

std::optional<catalog::Stage> stageOf(const fs::path& p) {
    return stageOfPath(p);
}

// Pipeline order: a task stage runs before its mesh stage, both before the fragment stage.
int pipelineRank(catalog::Stage s) {
    if (s == catalog::Stage::Task) return -2;
    if (s == catalog::Stage::Mesh) return -1;
    return static_cast<int>(s);
}

bool isVulkanOnly(catalog::Stage s) {
    return s > catalog::Stage::Compute;
}

bool isIdentifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string siblingPath(const std::string& stagePath, std::string_view ext) {
    return fs::path(stagePath).replace_extension(std::string(ext)).string();
}

void checkCompleteness(const ShaderInput& s, std::vector<Diagnostic>& out) {
    auto has = [&](catalog::Stage st) {
        return std::any_of(s.stages.begin(), s.stages.end(), [&](const StageFile& f) { return f.stage == st; });
    };
    const auto& any = s.stages.front().path;
    if (std::any_of(s.stages.begin(), s.stages.end(), [](const StageFile& f) { return isRayTracingStage(f.stage); })) {
        if (!std::all_of(s.stages.begin(), s.stages.end(),
                         [](const StageFile& f) { return isRayTracingStage(f.stage); }))
            out.push_back(
                makeError(any, 0, 0, "shader '" + s.name + "' mixes ray-tracing stages with other stages; rename one"));
        return;
    }
    if (has(catalog::Stage::Mesh) || has(catalog::Stage::Task)) {
        if (has(catalog::Stage::Vertex) || has(catalog::Stage::Geometry) || has(catalog::Stage::Compute))
            out.push_back(makeError(any, 0, 0,
                                    "shader '" + s.name +
                                        "' mixes a mesh pipeline with vertex, geometry or compute "
                                        "stages; rename one of them"));
        if (!has(catalog::Stage::Mesh))
            out.push_back(makeError(
                any, 0, 0,
                "shader '" + s.name + "' has a task stage but no mesh stage: expected " + siblingPath(any, ".mesh")));
        if (!has(catalog::Stage::Fragment))
            out.push_back(makeError(
                any, 0, 0, "shader '" + s.name + "' has no fragment stage: expected " + siblingPath(any, ".frag")));
        return;
    }
    if (has(catalog::Stage::Compute)) {
        if (s.stages.size() > 1)
            out.push_back(makeError(any, 0, 0,
                                    "shader '" + s.name +
                                        "' mixes a compute stage with graphics stages; "
                                        "rename one of them"));
        return;
    }
    if (!has(catalog::Stage::Vertex))
        out.push_back(
            makeError(any, 0, 0, "shader '" + s.name + "' has no vertex stage: expected " + siblingPath(any, ".vert")));
    if (!has(catalog::Stage::Fragment))
        out.push_back(makeError(
            any, 0, 0, "shader '" + s.name + "' has no fragment stage: expected " + siblingPath(any, ".frag")));
}

}  // namespace

std::optional<catalog::Stage> stageOfPath(const fs::path& p) {
    const auto ext = p.extension().string();
    for (int k = 0; k <= static_cast<int>(catalog::Stage::Callable); ++k) {
        const auto stage = static_cast<catalog::Stage>(k);
        if (ext.size() > 1 && ext.substr(1) == catalog::stageName(stage)) return stage;
    }
    return std::nullopt;
}

ShaderInputsResult collectShaderInputs(const std::vector<std::string>& inputs, bool vulkanClient) {
    ShaderInputsResult result;
    std::vector<std::string> files;
    for (const auto& in : inputs) {
        std::error_code ec;
        if (fs::is_directory(in, ec)) {
            std::vector<std::string> found;
            for (const auto& e : fs::directory_iterator(in, ec))
                if (e.is_regular_file() && stageOf(e.path())) found.push_back(e.path().string());
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (!fs::exists(in, ec)) {
            result.diagnostics.push_back(makeError(in, 0, 0, "no such file or directory"));
            result.ioError = true;
        } else if (!stageOf(in)) {
            result.diagnostics.push_back(
                makeError(in, 0, 0,
                          "unknown stage extension; use .vert, .geom, .frag or .comp (with --client vulkan also "
                          ".mesh, .task, .rgen, .rint, .rahit, .rchit, .rmiss or .rcall)"));
        } else {
            files.push_back(in);
        }
    }

    std::map<std::string, ShaderInput> byName;
    for (const auto& f : files) {
        auto name = fs::path(f).stem().string();
        auto stage = *stageOf(f);
        if (isVulkanOnly(stage) && !vulkanClient) {
            result.diagnostics.push_back(makeError(f, 0, 0,
                                                   "a ." + std::string(catalog::stageName(stage)) +
                                                       " stage is Vulkan GLSL: build it with --client vulkan "
                                                       "(prism_add_shaders(... CLIENT vulkan))"));
            continue;
        }
        auto& shader = byName[name];
        shader.name = name;
        auto dup = std::find_if(shader.stages.begin(), shader.stages.end(),
                                [&](const StageFile& s) { return s.stage == stage; });
        if (dup != shader.stages.end()) {
            if (fs::path(dup->path).lexically_normal() != fs::path(f).lexically_normal())
                result.diagnostics.push_back(makeError(f, 0, 0,
                                                       "second " + std::string(catalog::stageName(stage)) +
                                                           " stage for shader '" + name + "' (first: " + dup->path +
                                                           "); shader names must be unique"));
            continue;
        }
        shader.stages.push_back({stage, f});
    }
    for (auto& [name, shader] : byName) {
        std::sort(shader.stages.begin(), shader.stages.end(),
                  [](const StageFile& a, const StageFile& b) { return pipelineRank(a.stage) < pipelineRank(b.stage); });
        if (!isIdentifier(name)) {
            result.diagnostics.push_back(makeError(shader.stages.front().path, 0, 0,
                                                   "shader name '" + name +
                                                       "' is not a C++ identifier; rename the file "
                                                       "(letters, digits and '_')"));
            continue;
        }
        checkCompleteness(shader, result.diagnostics);
        result.shaders.push_back(std::move(shader));
    }
    return result;
}

}  // namespace prism::shaderc
