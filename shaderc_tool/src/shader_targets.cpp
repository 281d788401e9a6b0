// The targets each shader serves and the refusals of what a target cannot run
// (shader_targets.hpp).
#include "shader_targets.hpp"

namespace prism::shaderc {

ShaderTargets shaderTargets(const ResolvedCatalog& rc, std::size_t shader) {
    ShaderTargets result{{std::begin(kAllTargets), std::end(kAllTargets)}, nullptr};
    for (const auto& variant : rc.resolved[shader])
        for (const auto& stage : variant) {
            if (!stage.targetsPragma) continue;
            if (!result.declaration) result.declaration = &*stage.targetsPragma;
            std::erase_if(result.targets, [&](Target t) { return !hasTarget(stage.targetsPragma->targets, t); });
        }
    return result;
}

bool producedFor(const Options& o, const ResolvedCatalog& rc, std::size_t shader, Target target) {
    return hasTarget(o.targets, target) && hasTarget(shaderTargets(rc, shader).targets, target);
}

namespace {

// The stage kinds a target may refuse, in words ("a tessellation control stage").
std::string stageKindName(catalog::Stage stage) {
    switch (stage) {
        case catalog::Stage::Geometry: return "geometry";
        case catalog::Stage::Compute: return "compute";
        case catalog::Stage::TessControl: return "tessellation control";
        case catalog::Stage::TessEvaluation: return "tessellation evaluation";
        default: return std::string(catalog::stageName(stage));
    }
}

// A stage kind the target cannot run, in a shader that is to serve it.
Diagnostic refusedStage(const ResolvedCatalog& rc, std::size_t s, std::size_t st, Target target,
                        const ShaderTargets& declared) {
    const auto& name = rc.data.shaders[s].name;
    const auto kind = rc.data.shaders[s].variants.front().stages[st].stage;
    const std::string what = "shader '" + name + "' has a " + stageKindName(kind) + " stage, which " +
                             targetDescription(target) + " cannot run";
    if (declared.declaration)
        return makeError(declared.declaration->file, declared.declaration->line, 1,
                         what + " (" + rc.stagePaths[s][st] + "); remove " + std::string(targetName(target)) +
                             " from this #pragma prism targets");
    std::vector<Target> others;
    for (const Target t : kAllTargets)
        if (t != target) others.push_back(t);
    return makeError(rc.stagePaths[s][st], 0, 0,
                     what + "; add `#pragma prism targets " + targetListText(others) +
                         "` to one of its stage files to leave it out of " + std::string(targetName(target)) +
                         ", or drop " + std::string(targetName(target)) + " from --target");
}

// --variant SHADER:... names the shader explicitly: asking for a target it does not serve
// is an error, not a quiet omission.
std::vector<Diagnostic> explicitRequests(const Options& o, const ResolvedCatalog& rc, std::size_t s,
                                         const ShaderTargets& declared) {
    std::vector<Diagnostic> out;
    const auto& name = rc.data.shaders[s].name;
    for (const auto& filter : o.variantFilters) {
        if (filter.substr(0, filter.find(':')) != name) continue;
        for (const Target t : o.targets) {
            if (hasTarget(declared.targets, t)) continue;
            auto d = makeError(declared.declaration->file, declared.declaration->line, 1,
                               "--variant " + filter + " asks for shader '" + name + "' with --target " +
                                   std::string(targetName(t)) + ", but it declares only targets " +
                                   targetListText(declared.targets) + "; drop " + std::string(targetName(t)) +
                                   " from --target or this --variant");
            out.push_back(std::move(d));
        }
    }
    return out;
}

}  // namespace

std::vector<Diagnostic> checkShaderTargets(const Options& o, const ResolvedCatalog& rc) {
    std::vector<Diagnostic> out;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        if (rc.resolved[s].empty() || rc.data.shaders[s].variants.empty()) continue;
        const auto declared = shaderTargets(rc, s);
        if (declared.declaration) {
            auto asked = explicitRequests(o, rc, s, declared);
            out.insert(out.end(), asked.begin(), asked.end());
        }
        const auto& stages = rc.data.shaders[s].variants.front().stages;
        for (const Target t : o.targets) {
            if (!hasTarget(declared.targets, t)) continue;
            for (std::size_t st = 0; st < stages.size(); ++st)
                if (!targetRunsStage(t, stages[st].stage)) out.push_back(refusedStage(rc, s, st, t, declared));
        }
    }
    return out;
}

std::string targetProgramName(const ResolvedCatalog& rc, std::size_t shader, std::size_t variant) {
    const auto& s = rc.data.shaders[shader];
    return "'" + s.name + "'" + (s.variants.size() > 1 ? " (variant " + s.variants[variant].name + ")" : "");
}

void noteTarget(std::vector<Diagnostic>& diagnostics, const std::string& what) {
    for (auto& d : diagnostics)
        if (d.severity == Severity::Error) d.notes.push_back({Severity::Note, "", 0, 0, what, {}, {}});
}

}  // namespace prism::shaderc
