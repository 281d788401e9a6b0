// The spirv target: SPIR-V words, SPIRV-Tools validation and reflection of every program
// (spirv_target.hpp).
#include "spirv_target.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>

#include "shader_targets.hpp"
#include "validation_scheduler.hpp"
#include "validator.hpp"

namespace prism::shaderc {
namespace {

std::uint32_t setOf(const glslang::TObjectReflection& r) {
    const auto* t = r.getType();
    return t && t->getQualifier().hasSet() ? t->getQualifier().layoutSet : 0;
}

// glslang's reflection of the linked program (built after its locations and bindings were
// assigned: validator.cpp maps them first).
SpirvReflection reflectSpirv(glslang::TProgram& program) {
    SpirvReflection r;
    for (int b = 0; b < program.getNumUniformBlocks(); ++b) {
        const auto& block = program.getUniformBlock(b);
        SpirvBlock out{block.name,
                       setOf(block),
                       static_cast<std::uint32_t>(std::max(0, block.getBinding())),
                       static_cast<std::uint32_t>(std::max(0, block.size)),
                       {}};
        for (int i = 0; i < program.getNumUniformVariables(); ++i) {
            const auto& u = program.getUniform(i);
            if (u.index == b)
                out.members.push_back({u.name, static_cast<std::uint32_t>(u.glDefineType),
                                       static_cast<std::uint32_t>(std::max(0, u.offset)), std::max(1, u.size)});
        }
        std::sort(out.members.begin(), out.members.end(), [](auto& x, auto& y) { return x.offset < y.offset; });
        r.blocks.push_back(std::move(out));
    }
    for (int i = 0; i < program.getNumUniformVariables(); ++i) {
        const auto& u = program.getUniform(i);
        if (u.index >= 0 || !u.getType() || u.getType()->getBasicType() != glslang::EbtSampler) continue;
        r.samplers.push_back({u.name, static_cast<std::uint32_t>(u.glDefineType), setOf(u),
                              static_cast<std::uint32_t>(std::max(0, u.getBinding())), std::max(1, u.size)});
    }
    for (int i = 0; i < program.getNumPipeInputs(); ++i) {
        const auto& in = program.getPipeInput(i);
        if (in.name.rfind("gl_", 0) == 0 || !in.getType()) continue;
        const auto& q = in.getType()->getQualifier();
        r.inputs.push_back({in.name, static_cast<std::uint32_t>(in.glDefineType),
                            q.hasLocation() ? static_cast<int>(q.layoutLocation) : -1});
    }
    const auto bySlot = [](auto& x, auto& y) { return std::tie(x.set, x.binding) < std::tie(y.set, y.binding); };
    std::sort(r.blocks.begin(), r.blocks.end(), bySlot);
    std::sort(r.samplers.begin(), r.samplers.end(), bySlot);
    std::sort(r.inputs.begin(), r.inputs.end(), [](auto& x, auto& y) { return x.location < y.location; });
    return r;
}

// The check validateProgram runs on the linked program: SPIR-V of every stage, SPIRV-Tools'
// verdict on each, and the reflection, into `out`.
LinkedProgramCheck generateInto(const std::vector<StageToValidate>& stages, const std::string& program,
                                SpirvProgram& out) {
    return [&stages, program, &out](glslang::TProgram& linked, const std::vector<glslang::TShader*>&) {
        std::vector<Diagnostic> found;
        for (const auto& s : stages) {
            SpirvStage stage{s.stage, {}};
            std::string log;
            const std::string what = "program " + program + ", " + std::string(catalog::stageName(s.stage)) + " stage";
            if (!generateSpirv(linked, glslangStage(s.stage), stage.words, log)) {
                found.push_back(makeError(s.path, 0, 0, "glslang made no SPIR-V for " + what + ": " + log));
                continue;
            }
            auto invalid = validateSpirv(stage.words, kSpirvTargetEnv, s.path, what);
            found.insert(found.end(), invalid.begin(), invalid.end());
            out.stages.push_back(std::move(stage));
        }
        out.reflection = reflectSpirv(linked);
        return found;
    };
}

std::string programName(const CatalogShader& shader, const CatalogVariant& variant) {
    return "'" + shader.name + "'" + (shader.variants.size() > 1 ? " (variant " + variant.name + ")" : "");
}

}  // namespace

std::vector<Diagnostic> buildSpirvTarget(const Options& o, ResolvedCatalog& rc, const Contract& contract) {
    std::vector<std::pair<std::size_t, std::size_t>> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        if (!producedFor(o, rc, s, Target::Spirv)) continue;
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.emplace_back(s, v);
    }
    const auto run = [&](std::size_t i) {
        const auto [s, v] = programs[i];
        auto& shader = rc.data.shaders[s];
        std::vector<StageToValidate> stages;
        for (std::size_t st = 0; st < rc.resolved[s][v].size(); ++st)
            stages.push_back(
                {shader.variants[v].stages[st].stage, rc.stagePaths[s][st], rc.resolved[s][v][st], kSpirvTargetEnv});
        SpirvProgram program;
        auto result =
            validateProgram(stages, contract, generateInto(stages, programName(shader, shader.variants[v]), program));
        noteTarget(result.diagnostics, "for target spirv (Vulkan 1.1, relaxed rules) in program " +
                                           programName(shader, shader.variants[v]));
        if (result.ok && program.stages.size() == stages.size()) shader.variants[v].spirv = std::move(program);
        return std::move(result.diagnostics);
    };
    // The same token stream gives the same words and reflection.
    const auto share = [&](std::size_t from, std::size_t to) {
        rc.data.shaders[programs[to].first].variants[programs[to].second].spirv =
            rc.data.shaders[programs[from].first].variants[programs[from].second].spirv;
    };
    return runOncePerTokenKey(rc, contract, programs, o.jobs, run, share);
}

}  // namespace prism::shaderc
