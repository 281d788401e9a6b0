// Deduplicated, cached, multi-threaded validation of a catalogue (see
// validation_scheduler.hpp).
#include "validation_scheduler.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <thread>

#include <glslang/Public/ShaderLang.h>

#include "prism/hash/content_hash.hpp"
#include "job_pool.hpp"

namespace prism::shaderc {
namespace {

std::vector<StageToValidate> stagesOf(const ResolvedCatalog& rc, std::size_t s, std::size_t v) {
    std::vector<StageToValidate> stages;
    const auto& resolved = rc.resolved[s][v];
    for (std::size_t st = 0; st < resolved.size(); ++st)
        stages.push_back({rc.data.shaders[s].variants[v].stages[st].stage, rc.stagePaths[s][st], resolved[st]});
    return stages;
}

// What makes two builds of the tool validate alike: its version, glslang's, and this
// executable's size and time (a rebuilt tool never trusts an older build's results).
std::string toolIdentity() {
    static const std::string identity = [] {
        const auto v = glslang::GetVersion();
        std::string id = std::string(PRISM_VERSION) + " glslang " + std::to_string(v.major) + "." +
                         std::to_string(v.minor) + "." + std::to_string(v.patch);
        std::error_code ec;
        const auto exe = std::filesystem::canonical("/proc/self/exe", ec);
        if (!ec) {
            const auto size = std::filesystem::file_size(exe, ec);
            const auto time = std::filesystem::last_write_time(exe, ec).time_since_epoch().count();
            if (!ec) id += " " + std::to_string(size) + " " + std::to_string(time);
        }
        return id;
    }();
    return identity;
}

}  // namespace

ProgramKey programKey(const ResolvedCatalog& rc, const Contract& contract, std::size_t s, std::size_t v) {
    hash::ContentHash tokens;
    tokens.add("prism-shaderc validation").add(toolIdentity());
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

ValidationStats validateCatalogScheduled(ResolvedCatalog& rc, const Contract& contract, int jobs,
                                         ValidationCache& cache, DiagnosticSink& sink) {
    struct Program {
        std::size_t shader, variant;
        ProgramKey key;
    };
    const auto start = std::chrono::steady_clock::now();
    std::vector<Program> programs;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s)
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) programs.push_back({s, v, {}});
    runPool(programs.size(), jobs,
            [&](std::size_t i) { programs[i].key = programKey(rc, contract, programs[i].shader, programs[i].variant); });

    // One representative per token key, in catalogue order.
    std::map<std::string, std::size_t> groupOf;
    std::vector<std::size_t> representatives;
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (groupOf.try_emplace(programs[i].key.tokens, representatives.size()).second) representatives.push_back(i);

    ValidationStats stats;
    stats.programs = programs.size();
    stats.distinct = representatives.size();
    std::vector<std::optional<ValidatedVariant>> groupResults(representatives.size());
    std::vector<std::size_t> toValidate;
    for (std::size_t g = 0; g < representatives.size(); ++g) {
        groupResults[g] = cache.find(programs[representatives[g]].key);
        if (groupResults[g]) ++stats.fromCache;
        else toValidate.push_back(g);
    }
    if (!toValidate.empty()) initializeValidator();
    // Each distinct stage (kind, #version, token stream) of those programs is parsed
    // once, then shared by the programs using it.
    std::vector<std::vector<StageToValidate>> stageLists(toValidate.size());
    std::map<std::string, std::size_t> stageIndex;
    std::vector<const StageToValidate*> distinctStages;
    std::vector<std::vector<std::size_t>> stageRefs(toValidate.size());
    for (std::size_t i = 0; i < toValidate.size(); ++i) {
        const Program& p = programs[representatives[toValidate[i]]];
        stageLists[i] = stagesOf(rc, p.shader, p.variant);
    }
    for (std::size_t i = 0; i < toValidate.size(); ++i)
        for (const auto& st : stageLists[i]) {
            const std::string key = std::to_string(static_cast<int>(st.stage)) + " " + st.resolved.versionDirective +
                                    " " + st.resolved.validationKey;
            auto [it, fresh] = stageIndex.try_emplace(key, distinctStages.size());
            if (fresh) distinctStages.push_back(&st);
            stageRefs[i].push_back(it->second);
        }
    // A stage is parsed by the first program that needs it and freed after the last one:
    // glslang's trees of every stage at once cost more in fresh memory than the parses.
    struct StageSlot {
        std::once_flag parsed;
        std::shared_ptr<CompiledStage> compiled;
        std::atomic<std::size_t> users{0};
    };
    std::vector<StageSlot> slots(distinctStages.size());
    for (const auto& refs : stageRefs)
        for (auto k : refs) ++slots[k].users;
    runPool(toValidate.size(), jobs, [&](std::size_t i) {
        const std::size_t g = toValidate[i];
        const Program& p = programs[representatives[g]];
        std::vector<std::shared_ptr<CompiledStage>> mine;
        for (auto k : stageRefs[i]) {
            std::call_once(slots[k].parsed, [&] { slots[k].compiled = compileStage(*distinctStages[k]); });
            mine.push_back(slots[k].compiled);
        }
        groupResults[g] = validateCompiledProgram(stageLists[i], mine, contract);
        // Messages must speak of this program's own text, and a failed link leaves state
        // in shared stages: any message means a private run.
        if (!groupResults[g]->diagnostics.empty()) groupResults[g] = validateProgram(stageLists[i], contract);
        cache.store(p.key, *groupResults[g]);
        mine.clear();
        for (auto k : stageRefs[i])
            if (--slots[k].users == 0) slots[k].compiled.reset();
    });
    stats.validated = toValidate.size();
    stats.stagesCompiled = distinctStages.size();

    // A group result with diagnostics speaks of its representative's lines: the other
    // members (other texts) are validated on their own (rare: only when there are problems).
    std::vector<std::optional<ValidatedVariant>> results(programs.size());
    std::vector<std::size_t> ownRuns;
    for (std::size_t i = 0; i < programs.size(); ++i) {
        const std::size_t g = groupOf[programs[i].key.tokens];
        const Program& rep = programs[representatives[g]];
        if (groupResults[g]->diagnostics.empty() || rep.key.text == programs[i].key.text) {
            results[i] = groupResults[g];
        } else if (auto hit = cache.find(programs[i].key)) {
            results[i] = std::move(hit);
        } else {
            ownRuns.push_back(i);
        }
    }
    if (!ownRuns.empty() && toValidate.empty()) initializeValidator();
    runPool(ownRuns.size(), jobs, [&](std::size_t k) {
        const Program& p = programs[ownRuns[k]];
        results[ownRuns[k]] = validateProgram(stagesOf(rc, p.shader, p.variant), contract);
    });
    stats.validated += ownRuns.size();
    if (!toValidate.empty() || !ownRuns.empty()) finalizeValidator();
    cache.flush();
    stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    for (std::size_t i = 0; i < programs.size(); ++i) {
        const Program& p = programs[i];
        auto& shader = rc.data.shaders[p.shader];
        auto& variant = shader.variants[p.variant];
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
    return stats;
}

}  // namespace prism::shaderc
