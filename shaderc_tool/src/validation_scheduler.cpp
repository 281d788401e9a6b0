// Deduplicated, cached, multi-threaded validation of a catalogue (see
// validation_scheduler.hpp).
#include "validation_scheduler.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <optional>

#include "prism/hash/content_hash.hpp"
#include "job_pool.hpp"
#include "shared_stage_parses.hpp"
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

struct Program {
    std::size_t shader, variant;
    ProgramKey key;
};

// Phase 1: every variant's program with its content key, on -j threads.
std::vector<Program> keyPrograms(const ResolvedCatalog& rc, const Contract& contract, int jobs) {
    std::vector<Program> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s)
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.push_back({s, v, {}});
    runPool(programs.size(), jobs, [&](std::size_t i) {
        programs[i].key = programKey(rc, contract, programs[i].shader, programs[i].variant);
    });
    return programs;
}

// Phase 2: programs with one token key form a group; its first program represents it.
struct Groups {
    std::map<std::string, std::size_t> byTokens;  // token key -> group
    std::vector<std::size_t> representatives;     // group -> program, in catalogue order
    std::vector<std::optional<ValidatedVariant>> results;
};

Groups groupByTokens(const std::vector<Program>& programs) {
    Groups groups;
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (groups.byTokens.try_emplace(programs[i].key.tokens, groups.representatives.size()).second)
            groups.representatives.push_back(i);
    groups.results.resize(groups.representatives.size());
    return groups;
}

// Phase 3: the groups the cache answers; returns the others.
std::vector<std::size_t> lookUpGroups(const std::vector<Program>& programs, Groups& groups,
                                      const ValidationCache& cache) {
    std::vector<std::size_t> toValidate;
    for (std::size_t g = 0; g < groups.representatives.size(); ++g) {
        groups.results[g] = cache.find(programs[groups.representatives[g]].key);
        if (!groups.results[g]) toValidate.push_back(g);
    }
    return toValidate;
}

// Phase 4: the stages of each group to validate ([i]: group toValidate[i]'s).
std::vector<std::vector<StageToValidate>> stageLists(const ResolvedCatalog& rc, const std::vector<Program>& programs,
                                                     const Groups& groups, const std::vector<std::size_t>& toValidate) {
    std::vector<std::vector<StageToValidate>> lists(toValidate.size());
    for (std::size_t i = 0; i < toValidate.size(); ++i) {
        const Program& p = programs[groups.representatives[toValidate[i]]];
        lists[i] = stagesOf(rc, p.shader, p.variant);
    }
    return lists;
}

// Phase 5: validates the groups on -j threads, each distinct stage parsed once
// (shared_stage_parses.hpp), and stores their results.
void validateGroups(const std::vector<Program>& programs, Groups& groups, const std::vector<std::size_t>& toValidate,
                    const std::vector<std::vector<StageToValidate>>& lists, SharedStageParses& parses,
                    const Contract& contract, int jobs, ValidationCache& cache) {
    runPool(toValidate.size(), jobs, [&](std::size_t i) {
        auto& result = groups.results[toValidate[i]];
        result = validateCompiledProgram(lists[i], parses.acquire(i), contract);
        parses.release(i);
        // Messages must speak of this program's own text, and a failed link leaves state
        // in shared stages: any message means a private run.
        if (!result->diagnostics.empty()) result = validateProgram(lists[i], contract);
        cache.store(programs[groups.representatives[toValidate[i]]].key, *result);
    });
}

// Phase 6: each program's result. A group result with diagnostics speaks of its
// representative's lines: the other members (other texts) take the cache's result for
// their own text, else are returned in `ownRuns` (rare: only when there are problems).
std::vector<std::optional<ValidatedVariant>> programResults(const std::vector<Program>& programs, const Groups& groups,
                                                            const ValidationCache& cache,
                                                            std::vector<std::size_t>& ownRuns) {
    std::vector<std::optional<ValidatedVariant>> results(programs.size());
    for (std::size_t i = 0; i < programs.size(); ++i) {
        const std::size_t g = groups.byTokens.at(programs[i].key.tokens);
        const Program& rep = programs[groups.representatives[g]];
        if (groups.results[g]->diagnostics.empty() || rep.key.text == programs[i].key.text) {
            results[i] = groups.results[g];
        } else if (auto hit = cache.find(programs[i].key)) {
            results[i] = std::move(hit);
        } else {
            ownRuns.push_back(i);
        }
    }
    return results;
}

// Phase 7: diagnostics (errors of a shader with variants name the variant) and reflection.
void reportResults(ResolvedCatalog& rc, const std::vector<Program>& programs,
                   std::vector<std::optional<ValidatedVariant>>& results, DiagnosticSink& sink) {
    for (std::size_t i = 0; i < programs.size(); ++i) {
        auto& shader = rc.data.shaders[programs[i].shader];
        auto& variant = shader.variants[programs[i].variant];
        for (auto d : results[i]->diagnostics) {
            if (shader.variants.size() > 1 && d.severity == Severity::Error)
                d.notes.push_back({Severity::Note,
                                   "",
                                   0,
                                   0,
                                   "in variant " + variant.name + " of shader '" + shader.name + "'",
                                   {},
                                   {}});
            sink.report(std::move(d));
        }
        variant.reflection = std::move(results[i]->reflection);
    }
}

}  // namespace

ValidationStats validateCatalogScheduled(ResolvedCatalog& rc, const Contract& contract, int jobs,
                                         ValidationCache& cache, DiagnosticSink& sink) {
    const auto start = std::chrono::steady_clock::now();
    const auto programs = keyPrograms(rc, contract, jobs);
    auto groups = groupByTokens(programs);
    const auto toValidate = lookUpGroups(programs, groups, cache);
    if (!toValidate.empty()) initializeValidator();
    const auto lists = stageLists(rc, programs, groups, toValidate);
    SharedStageParses parses(lists);
    validateGroups(programs, groups, toValidate, lists, parses, contract, jobs, cache);
    std::vector<std::size_t> ownRuns;
    auto results = programResults(programs, groups, cache, ownRuns);
    if (!ownRuns.empty() && toValidate.empty()) initializeValidator();
    runPool(ownRuns.size(), jobs, [&](std::size_t k) {
        const Program& p = programs[ownRuns[k]];
        results[ownRuns[k]] = validateProgram(stagesOf(rc, p.shader, p.variant), contract);
    });
    if (!toValidate.empty() || !ownRuns.empty()) finalizeValidator();
    cache.flush();

    ValidationStats stats;
    stats.programs = programs.size();
    stats.distinct = groups.representatives.size();
    stats.fromCache = groups.representatives.size() - toValidate.size();
    stats.validated = toValidate.size() + ownRuns.size();
    stats.stagesCompiled = parses.distinct();
    stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    reportResults(rc, programs, results, sink);
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
