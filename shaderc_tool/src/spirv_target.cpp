// The spirv target: the Vulkan path with relaxed rules over every program (spirv_target.hpp).
#include "spirv_target.hpp"

#include "shader_targets.hpp"
#include "validation_scheduler.hpp"
#include "validator.hpp"

namespace prism::shaderc {

std::vector<Diagnostic> buildSpirvTarget(const Options& o, ResolvedCatalog& rc, const Contract& contract) {
    std::vector<std::pair<std::size_t, std::size_t>> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        if (o.spirvEnv || !producedFor(o, rc, s, Target::Spirv)) continue;
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.emplace_back(s, v);
    }
    const auto run = [&](std::size_t i) {
        const auto [s, v] = programs[i];
        auto& shader = rc.data.shaders[s];
        std::vector<StageToValidate> stages;
        for (std::size_t st = 0; st < rc.resolved[s][v].size(); ++st)
            stages.push_back({shader.variants[v].stages[st].stage, rc.stagePaths[s][st], rc.resolved[s][v][st],
                              kSpirvTargetEnv, shader.name, true});
        auto result = validateProgram(stages, contract);
        noteTarget(result.diagnostics,
                   "for target spirv (Vulkan 1.1, relaxed rules) in program " + targetProgramName(rc, s, v));
        if (result.ok && result.reflection.spirv.size() == stages.size())
            shader.variants[v].spirv = std::move(result.reflection);
        return std::move(result.diagnostics);
    };
    // The same token stream gives the same words and reflection.
    const auto share = [&](std::size_t from, std::size_t to) {
        rc.data.shaders[programs[to].first].variants[programs[to].second].spirv =
            rc.data.shaders[programs[from].first].variants[programs[from].second].spirv;
    };
    return runOncePerTokenKey(tokenRepresentatives(rc, contract, programs), o.jobs, run, share);
}

}  // namespace prism::shaderc
