// Every target's scheduling: token groups, their cache pack, and the runs
// (target_scheduler.hpp).
#include "target_scheduler.hpp"

#include <map>
#include <string>

#include "job_pool.hpp"
#include "validation_scheduler.hpp"
#include "validation_settings.hpp"

namespace prism::shaderc {
namespace {

// A result that may be shared, cached or taken from the cache: no message of any kind.
bool clean(const std::optional<ValidatedVariant>& result) {
    return result && result->ok && result->diagnostics.empty();
}

}  // namespace

std::vector<std::size_t> TargetPrograms::firstRuns() const {
    std::vector<std::size_t> runs;
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (runsFirst(i)) runs.push_back(i);
    return runs;
}

std::size_t TargetPrograms::fromCache() const {
    std::size_t count = 0;
    for (const auto& c : cached) count += c.has_value();
    return count;
}

TargetPrograms scheduleTarget(const ResolvedCatalog& rc, const Contract& contract, Target target,
                              std::vector<std::pair<std::size_t, std::size_t>> programs, ValidationCache& cache,
                              int jobs) {
    TargetPrograms s;
    s.target = target;
    s.programs = std::move(programs);
    s.cache = &cache;
    s.keys.resize(s.programs.size());
    runPool(s.programs.size(), jobs,
            [&](std::size_t i) { s.keys[i] = programKey(rc, contract, s.programs[i].first, s.programs[i].second); });
    std::map<std::string, std::size_t> firstOfKey;
    for (std::size_t i = 0; i < s.programs.size(); ++i) {
        s.representatives.push_back(firstOfKey.try_emplace(s.keys[i].tokens, i).first->second);
        std::optional<ValidatedVariant> hit;
        if (s.representatives[i] == i) hit = s.cache->find(s.keys[i]);
        s.cached.push_back(clean(hit) ? std::move(hit) : std::nullopt);
    }
    return s;
}

TargetPrograms scheduleTarget(const Options& o, const ResolvedCatalog& rc, const Contract& contract, Target target,
                              std::vector<std::pair<std::size_t, std::size_t>> programs) {
    if (programs.empty()) {
        TargetPrograms none;
        none.target = target;
        return none;
    }
    // The target's own pack beside the gl one: one catalogue, one pack per target.
    const std::string pack =
        catalogueCacheKey(o) + (target == Target::Gl ? std::string() : "-" + std::string(targetName(target)));
    auto cache = std::make_unique<ValidationCache>(validationCacheDir(o), pack);
    auto s = scheduleTarget(rc, contract, target, std::move(programs), *cache, o.jobs);
    s.ownCache = std::move(cache);
    return s;
}

std::vector<Diagnostic> runTarget(TargetPrograms& s, int jobs, const TargetValidate& validate, const TargetKeep& keep) {
    const std::size_t count = s.programs.size();
    if (count == 0) return {};
    std::vector<std::optional<ValidatedVariant>> results(count);
    const auto first = s.firstRuns();
    initializeValidator();
    runPool(first.size(), jobs, [&](std::size_t k) { results[first[k]] = validate(first[k], true); });
    std::vector<std::size_t> ownRuns;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t rep = s.representatives[i];
        if (rep == i && s.cached[i]) results[i] = std::move(s.cached[i]);
        if (rep == i) continue;
        if (clean(results[rep]))
            results[i] = results[rep];
        else
            ownRuns.push_back(i);
    }
    runPool(ownRuns.size(), jobs, [&](std::size_t k) { results[ownRuns[k]] = validate(ownRuns[k], false); });
    finalizeValidator();
    s.validated = first.size() + ownRuns.size();
    for (const auto i : first)
        if (clean(results[i])) s.cache->store(s.keys[i], *results[i]);
    s.cache->flush();
    std::vector<Diagnostic> out;
    for (std::size_t i = 0; i < count; ++i) {
        keep(i, *results[i]);
        out.insert(out.end(), results[i]->diagnostics.begin(), results[i]->diagnostics.end());
    }
    return out;
}

}  // namespace prism::shaderc
