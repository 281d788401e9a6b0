// The spirv target: the Vulkan path with relaxed rules over every program (spirv_target.hpp).
#include "spirv_target.hpp"

#include <iostream>

#include "shader_targets.hpp"
#include "target_scheduler.hpp"
#include "validator.hpp"

namespace prism::shaderc {
namespace {

using SpirvProgram = std::pair<std::size_t, std::size_t>;  // shader, variant

ValidatedVariant compileProgram(const ResolvedCatalog& rc, const SpirvProgram& p, const Contract& contract) {
    const auto [s, v] = p;
    const auto& shader = rc.data.shaders[s];
    std::vector<StageToValidate> stages;
    for (std::size_t st = 0; st < rc.resolved[s][v].size(); ++st)
        stages.push_back({shader.variants[v].stages[st].stage, rc.stagePaths[s][st], rc.resolved[s][v][st],
                          spirvTargetRules(), shader.name});
    auto result = validateProgram(stages, contract);
    noteTarget(result.diagnostics,
               "for target spirv (Vulkan 1.1, relaxed rules) in program " + targetProgramName(rc, s, v));
    result.ok = result.ok && result.reflection.spirv.size() == stages.size();
    return result;
}

// --stats: how much was shared or cached, and what SPIRV-Tools' validator cost.
void printSpirvStats(const TargetPrograms& scheduled, const SpirvValidatorUse& before) {
    std::size_t shared = 0;
    for (std::size_t i = 0; i < scheduled.programs.size(); ++i) shared += scheduled.representatives[i] != i;
    const auto use = spirvValidatorUse();
    std::cerr << "prism-shaderc: spirv: compiled " << scheduled.programs.size() << " programs (" << shared
              << " shared a token stream, " << scheduled.fromCache() << " from the cache); SPIRV-Tools validated "
              << use.modules - before.modules << " modules in " << static_cast<int>(use.cpuMs - before.cpuMs + 0.5)
              << " ms of CPU\n";
}

// A client that compiles to SPIR-V (the Vulkan client's rules) validated it in stage 5: each
// variant's SPIR-V is its reflection.
void keepClientSpirv(CatalogData& c) {
    for (auto& s : c.shaders)
        for (auto& v : s.variants)
            if (!v.reflection.spirv.empty()) v.spirv = v.reflection;
}

}  // namespace

std::vector<Diagnostic> buildSpirvTarget(const Options& o, ResolvedCatalog& rc, const Contract& contract) {
    if (o.rules.spirvEnv) {
        keepClientSpirv(rc.data);
        return {};
    }
    std::vector<SpirvProgram> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        if (!producedFor(o, rc, s, Target::Spirv)) continue;
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.emplace_back(s, v);
    }
    const auto before = spirvValidatorUse();
    auto scheduled = scheduleTarget(o, rc, contract, Target::Spirv, std::move(programs));
    // The same token stream gives the same words and reflection.
    auto diagnostics = runTarget(
        scheduled, o.jobs, [&](std::size_t i, bool) { return compileProgram(rc, scheduled.programs[i], contract); },
        [&](std::size_t i, const ValidatedVariant& result) {
            if (result.ok)
                rc.data.shaders[scheduled.programs[i].first].variants[scheduled.programs[i].second].spirv =
                    result.reflection;
        });
    if (o.printStats && !scheduled.programs.empty()) printSpirvStats(scheduled, before);
    return diagnostics;
}

}  // namespace prism::shaderc
