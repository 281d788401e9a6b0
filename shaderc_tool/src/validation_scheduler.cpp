// Deduplicated, cached, multi-threaded validation of a catalogue (see
// validation_scheduler.hpp).
#include "validation_scheduler.hpp"

#include <chrono>
#include <iostream>
#include <utility>

#include "prism/hash/content_hash.hpp"
#include "shared_stage_parses.hpp"
#include "target_scheduler.hpp"
#include "tool_identity.hpp"
#include "validation_settings.hpp"

namespace prism::shaderc {
namespace {

std::vector<StageToValidate> stagesOf(const ResolvedCatalog& rc, std::size_t s, std::size_t v) {
    std::vector<StageToValidate> stages;
    const auto& resolved = rc.resolved[s][v];
    for (std::size_t st = 0; st < resolved.size(); ++st)
        stages.push_back({rc.data.shaders[s].variants[v].stages[st].stage, rc.stagePaths[s][st], resolved[st],
                          rc.data.rules, rc.data.shaders[s].name});
    return stages;
}

}  // namespace

ProgramKey programKey(const ResolvedCatalog& rc, const Contract& contract, std::size_t s, std::size_t v) {
    hash::ContentHash tokens;
    tokens.add("prism-shaderc validation").add(toolIdentity());
    if (rc.data.rules.spirvEnv) tokens.add("client").add(spirvEnvName(*rc.data.rules.spirvEnv));
    for (const auto& a : contract.attributes) tokens.add(a.name).add(a.type).add(std::to_string(a.location));
    tokens.add("uniforms");
    for (const auto& u : contract.uniforms) tokens.add(u.name).add(u.type).add(std::to_string(u.array));
    const auto& resolved = rc.resolved[s][v];
    const auto& variant = rc.data.shaders[s].variants[v];
    for (std::size_t st = 0; st < resolved.size(); ++st) {
        tokens.add(std::to_string(static_cast<int>(variant.stages[st].stage)))
            .add(resolved[st].versionDirective)
            .add(resolved[st].validationKey);
    }
    hash::ContentHash text;
    text.add(tokens.hex());
    for (const auto& f : contract.files) text.add(f);
    for (std::size_t st = 0; st < resolved.size(); ++st) {
        text.add(rc.stagePaths[s][st]).add(resolved[st].text);
        for (const auto& file : resolved[st].files) {
            text.add(file.path);
            for (const auto& site : file.chain) text.add(site.file).add(std::to_string(site.line));
        }
    }
    return {tokens.hex(), text.hex()};
}

namespace {

std::vector<std::pair<std::size_t, std::size_t>> everyVariant(const ResolvedCatalog& rc) {
    std::vector<std::pair<std::size_t, std::size_t>> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s)
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.emplace_back(s, v);
    return programs;
}

// One program's diagnostics (errors of a shader with variants name the variant) and reflection.
void reportResult(ResolvedCatalog& rc, std::pair<std::size_t, std::size_t> program, const ValidatedVariant& result,
                  DiagnosticSink& sink) {
    auto& shader = rc.data.shaders[program.first];
    auto& variant = shader.variants[program.second];
    for (auto d : result.diagnostics) {
        if (shader.variants.size() > 1 && d.severity == Severity::Error)
            d.notes.push_back(
                {Severity::Note, "", 0, 0, "in variant " + variant.name + " of shader '" + shader.name + "'", {}, {}});
        sink.report(std::move(d));
    }
    variant.reflection = result.reflection;
}

}  // namespace

ValidationStats validateCatalogScheduled(ResolvedCatalog& rc, const Contract& contract, int jobs,
                                         ValidationCache& cache, DiagnosticSink& sink) {
    const auto start = std::chrono::steady_clock::now();
    auto scheduled = scheduleTarget(rc, contract, Target::Gl, everyVariant(rc), cache, jobs);
    const auto& programs = scheduled.programs;
    std::vector<std::vector<StageToValidate>> lists(programs.size());  // the first runs' stages
    for (const auto i : scheduled.firstRuns()) lists[i] = stagesOf(rc, programs[i].first, programs[i].second);
    SharedStageParses parses(lists);
    runTarget(
        scheduled, jobs,
        [&](std::size_t i, bool groupRun) {
            if (groupRun) {
                auto result = validateCompiledProgram(lists[i], parses.acquire(i), contract);
                parses.release(i);
                // Messages must speak of this program's own text, and a failed link leaves
                // state in shared stages: any message means a private run.
                if (result.diagnostics.empty()) return result;
                return validateProgram(lists[i], contract);
            }
            return validateProgram(stagesOf(rc, programs[i].first, programs[i].second), contract);  // own lines
        },
        [&](std::size_t i, const ValidatedVariant& result) { reportResult(rc, programs[i], result, sink); });

    ValidationStats stats;
    stats.programs = programs.size();
    for (std::size_t i = 0; i < programs.size(); ++i) stats.distinct += scheduled.representatives[i] == i;
    stats.fromCache = scheduled.fromCache();
    stats.validated = scheduled.validated;
    stats.stagesCompiled = parses.distinct();
    stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

Validation validateCatalog(const Options& o, ResolvedCatalog& catalog, const Contract& contract) {
    ValidationCache cache(validationCacheDir(o), catalogueCacheKey(o));
    DiagnosticSink sink;
    Validation validation;
    validation.stats = validateCatalogScheduled(catalog, contract, o.jobs, cache, sink);
    validation.diagnostics = sink.diagnostics();
    if (o.printStats) {
        printResolutionStats(std::cerr, catalog);
        printValidationStats(std::cerr, validation.stats);
    }
    return validation;
}

}  // namespace prism::shaderc
