// The es300 target's text and its validation as GLSL ES 3.00 (es300_target.hpp).
#include "es300_target.hpp"

#include <prism/catalog/line_directive.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "es300_limits.hpp"
#include "shader_targets.hpp"
#include "shared_stage_parses.hpp"
#include "target_scheduler.hpp"
#include "validator.hpp"

namespace prism::shaderc {
namespace {

// Every sampler type of GLSL ES 3.00 at highp, with float and int. ES gives float no default
// precision in a fragment shader, sampler2D and samplerCube a default of lowp in every stage,
// and the other samplers none (GLSL ES 3.00 §4.5.4), so a G-buffer read through a sampler2D
// would be lowp on a phone. highp keeps the modules' small thresholds (a 1e-20 in
// safeNormalize underflows at mediump); a module's own `precision` line still wins.
constexpr const char* kHighpDefaults =
    "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\nprecision highp samplerCube;\n"
    "precision highp sampler3D;\nprecision highp samplerCubeShadow;\n"
    "precision highp sampler2DShadow;\nprecision highp sampler2DArray;\nprecision highp sampler2DArrayShadow;\n"
    "precision highp isampler2D;\nprecision highp isampler3D;\nprecision highp isamplerCube;\n"
    "precision highp isampler2DArray;\nprecision highp usampler2D;\nprecision highp usampler3D;\n"
    "precision highp usamplerCube;\nprecision highp usampler2DArray;\n";

constexpr const char* kEsVersion = "#version 300 es";

// `#line N S` names the next line N in ES; before GLSL 3.30 it named N + 1, so such a
// stage's directives move by one (prism/catalog/line_directive.hpp).
std::string retargetLineDirectives(const std::string& body, const catalog::GlslVersionTag from) {
    const auto es = catalog::glslVersionOf(kEsVersion);
    if (catalog::lineDirectiveNamesNextLine(from) == catalog::lineDirectiveNamesNextLine(es)) return body;
    std::istringstream in(body);
    std::string out, line;
    while (std::getline(in, line)) {
        unsigned n = 0, s = 0;
        if (std::sscanf(line.c_str(), "#line %u %u", &n, &s) == 2)
            line = catalog::lineDirective(catalog::lineAfterDirective(static_cast<int>(n), from), s, es);
        out += line + "\n";
    }
    return out;
}

}  // namespace

std::string es300Text(const std::string& desktop) {
    const auto firstLineEnd = desktop.find('\n');
    const std::string version = desktop.substr(0, firstLineEnd);
    const std::string body = firstLineEnd == std::string::npos ? "" : desktop.substr(firstLineEnd + 1);
    return std::string(kEsVersion) + "\n" + kHighpDefaults +
           retargetLineDirectives(body, catalog::glslVersionOf(version));
}

ResolvedStage es300Stage(const ResolvedStage& desktop) {
    ResolvedStage es = desktop;
    es.versionDirective = kEsVersion;
    es.versionNumber = 300;
    es.text = es300Text(desktop.text);
    return es;
}

namespace {

using EsProgram = std::pair<std::size_t, std::size_t>;  // shader, variant

std::vector<StageToValidate> es300Stages(const ResolvedCatalog& rc, const EsProgram& p) {
    std::vector<StageToValidate> stages;
    const auto& resolved = rc.resolved[p.first][p.second];
    for (std::size_t st = 0; st < resolved.size(); ++st)
        stages.push_back({rc.data.shaders[p.first].variants[p.second].stages[st].stage, rc.stagePaths[p.first][st],
                          es300Stage(resolved[st])});
    return stages;
}

// A group's first run takes the shared parses of its stages; a message, or a program
// that runs on its own for its own lines, means a run on private ones (as for gl).
ValidatedVariant validateOne(const ResolvedCatalog& rc, const EsProgram& p, const Contract& contract,
                             const std::vector<StageToValidate>& stages, SharedStageParses* shared, std::size_t index) {
    const std::string program = targetProgramName(rc, p.first, p.second);
    Es300StagePaths paths{stages.front().path, stages.back().path};
    for (const auto& st : stages) (st.stage == catalog::Stage::Fragment ? paths.fragment : paths.vertex) = st.path;
    const auto limits = es300LimitsCheck(program, paths);
    ValidatedVariant result;
    if (shared) {
        result = validateCompiledProgram(stages, shared->acquire(index), contract, limits);
        shared->release(index);
    }
    if (!shared || !result.diagnostics.empty()) result = validateProgram(stages, contract, limits);
    noteTarget(result.diagnostics,
               "for target es300 (GLSL ES 3.00) in program " + program +
                   "; `#pragma prism targets gl spirv` in a stage file leaves a shader out of es300");
    result.reflection = {};  // es300 keeps only the verdict; the gl reflection serves it
    return result;
}

// --stats: how much of the es300 validation was shared or cached, as for gl.
void printEs300Stats(const TargetPrograms& scheduled, std::size_t stagesParsed) {
    std::size_t shared = 0;
    for (std::size_t i = 0; i < scheduled.programs.size(); ++i) shared += scheduled.representatives[i] != i;
    std::cerr << "prism-shaderc: es300: validated " << scheduled.programs.size() << " programs (" << shared
              << " shared a token stream, " << scheduled.fromCache() << " from the cache; " << stagesParsed
              << " stages parsed)\n";
}

std::vector<EsProgram> es300Programs(const Options& o, const ResolvedCatalog& rc) {
    std::vector<EsProgram> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        if (!producedFor(o, rc, s, Target::Es300)) continue;
        const auto& variants = rc.data.shaders[s].variants;
        const bool runnable =
            !variants.empty() &&
            std::all_of(variants.front().stages.begin(), variants.front().stages.end(),
                        [](const CatalogStage& st) { return targetRunsStage(Target::Es300, st.stage); });
        for (std::size_t v = 0; runnable && v < variants.size(); ++v) programs.emplace_back(s, v);
    }
    return programs;
}

}  // namespace

std::vector<Diagnostic> validateEs300(const Options& o, ResolvedCatalog& rc, const Contract& contract) {
    auto scheduled = scheduleTarget(o, rc, contract, Target::Es300, es300Programs(o, rc));
    const auto& programs = scheduled.programs;
    std::vector<std::vector<StageToValidate>> lists(programs.size());  // the first runs' stages
    for (const auto i : scheduled.firstRuns()) lists[i] = es300Stages(rc, programs[i]);
    SharedStageParses parses(lists);
    auto diagnostics = runTarget(
        scheduled, o.jobs,
        [&](std::size_t i, bool groupRun) {
            if (groupRun) return validateOne(rc, programs[i], contract, lists[i], &parses, i);
            return validateOne(rc, programs[i], contract, es300Stages(rc, programs[i]), nullptr, i);  // own lines
        },
        [&](std::size_t i, const ValidatedVariant& result) {
            rc.data.shaders[programs[i].first].variants[programs[i].second].es300 = result.ok;
        });
    if (o.printStats && !programs.empty()) printEs300Stats(scheduled, parses.parsed());
    return diagnostics;
}

}  // namespace prism::shaderc
