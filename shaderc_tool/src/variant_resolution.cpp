// Parallel resolution of a shader's variants, sharing what cannot differ (see
// variant_resolution.hpp).
#include "variant_resolution.hpp"

#include <cctype>
#include <deque>
#include <map>
#include <optional>
#include <set>

#include "job_pool.hpp"
#include "structural_macros.hpp"
#include "validation_key.hpp"

namespace prism::shaderc {
namespace {

using Defines = std::vector<std::pair<std::string, std::string>>;

// A run made for real, which variants may share.
struct Representative {
    const ResolveResult* result;
    const ResolveOptions* options;
    std::optional<StructuralMacros> structure;  // nullopt: nothing may share this run
};

std::optional<StructuralMacros> structureOf(const ResolveResult& r, const SourceReader& reader) {
    if (!r.ok || !r.diagnostics.empty()) return std::nullopt;  // its messages might not be a variant's
    std::vector<std::string> texts;
    for (const auto& path : r.stage.filesRead) {
        auto text = reader.read(path);
        if (!text) return std::nullopt;
        texts.push_back(std::move(*text));
    }
    return structuralMacros(std::vector<std::string_view>(texts.begin(), texts.end()));
}

const std::string* valueOf(const Defines& defines, const std::string& name) {
    for (const auto& [n, v] : defines)
        if (n == name) return &v;
    return nullptr;
}

// A value that names a macro of the files read expands into it, which the preprocessor
// limits (preprocessor_limits.hpp) checked for the representative's value only.
bool namesAMacro(const std::string* value, const StructuralMacros& s) {
    return value && !value->empty() && !std::isdigit(static_cast<unsigned char>(value->front())) &&
           value->front() != '-' && s.defined.contains(*value);
}

// May a run with `options` take `rep`'s result? Only when every macro on which they
// differ is structural in none of the files `rep` read.
bool mayShare(const Representative& rep, const ResolveOptions& options) {
    if (!rep.structure) return false;
    const auto differs = [&](const Defines& a, const Defines& b) {
        for (const auto& [name, value] : a) {
            const std::string* other = valueOf(b, name);
            if (other && *other == value) continue;
            if (rep.structure->decisive.contains(name) || namesAMacro(&value, *rep.structure) ||
                namesAMacro(other, *rep.structure))
                return true;
        }
        return false;
    };
    return !differs(options.defines, rep.options->defines) && !differs(rep.options->defines, options.defines);
}

// `from`'s result for a run with `options`: the same files and decisions; only the
// #define block at the top differs.
ResolveResult withDefines(const ResolveResult& from, const ResolveOptions& fromOptions, const ResolveOptions& options) {
    ResolveResult r = from;
    std::size_t end = 0;
    for (std::size_t line = 0; line < 1 + fromOptions.defines.size(); ++line) end = r.stage.text.find('\n', end) + 1;
    std::string head = r.stage.text.substr(0, r.stage.text.find('\n') + 1);  // the #version line
    for (const auto& [name, value] : options.defines)
        head += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    r.stage.text = head + r.stage.text.substr(end);
    r.stage.shared = true;
    return r;
}

// One shader's variants being resolved: results[variant][stage], and the run each result
// was taken from (nullptr: the base run was not taken, the result is its own run).
struct Resolution {
    std::vector<std::vector<ResolveResult>> results;
    std::vector<ResolveOptions> options;  // [variant]: the base options and its defines
    std::vector<std::vector<char>> done;
    std::vector<std::vector<const Representative*>> origin;
    std::vector<std::deque<Representative>> reps;  // [stage]; a deque: `origin` points into it
    bool share = true;
};

Resolution startResolution(std::size_t stages, const ResolveOptions& base, const std::vector<VariantChoice>& choices,
                           const std::vector<ResolveResult>& baseRuns, bool share, const SourceReader& reader) {
    const std::size_t variants = choices.size();
    Resolution r;
    r.share = share;
    r.results.assign(variants, std::vector<ResolveResult>(stages));
    r.options.assign(variants, base);
    for (std::size_t v = 0; v < variants; ++v)
        r.options[v].defines.insert(r.options[v].defines.end(), choices[v].defines.begin(), choices[v].defines.end());
    r.done.assign(variants, std::vector<char>(stages, 0));
    r.origin.assign(variants, std::vector<const Representative*>(stages));
    r.reps.resize(stages);
    if (share && baseRuns.size() == stages)
        for (std::size_t st = 0; st < stages; ++st)
            r.reps[st].push_back({&baseRuns[st], &base, structureOf(baseRuns[st], reader)});
    return r;
}

// Takes the result of a run that variant `v` may share, if any.
bool takeShared(Resolution& r, std::size_t v, std::size_t st) {
    if (!r.share) return false;
    for (const auto& rep : r.reps[st]) {
        if (!mayShare(rep, r.options[v])) continue;
        r.results[v][st] = withDefines(*rep.result, *rep.options, r.options[v]);
        r.origin[v][st] = &rep;
        r.done[v][st] = 1;
        return true;
    }
    return false;
}

// The group of variant `v` in `round`: the values of the macros that the first
// representative found structural; the first variant alone when there is no
// representative yet; each variant alone when the first has no structure, or from round 2 on.
std::vector<std::string> groupOf(const Resolution& r, const VariantChoice& choice, std::size_t v, std::size_t st,
                                 int round) {
    std::vector<std::string> group;
    if (r.share && r.reps[st].empty()) {
        group.push_back("first");
    } else if (r.share && round < 2 && r.reps[st].front().structure) {
        for (const auto& [name, value] : choice.defines)
            group.push_back(r.reps[st].front().structure->decisive.contains(name) ? value : "\x01");
    } else {
        group.push_back(std::to_string(v));
    }
    return group;
}

// One round: shares what can be shared, and returns the (variant, stage) runs to make:
// one per group (every one without sharing).
std::vector<std::pair<std::size_t, std::size_t>> planRound(Resolution& r, const std::vector<VariantChoice>& choices,
                                                           int round) {
    std::vector<std::pair<std::size_t, std::size_t>> toRun;
    for (std::size_t st = 0; st < r.reps.size(); ++st) {
        std::set<std::vector<std::string>> groupsTaken;
        for (std::size_t v = 0; v < choices.size(); ++v) {
            if (r.done[v][st] || takeShared(r, v, st)) continue;
            if (groupsTaken.insert(groupOf(r, choices[v], v, st, round)).second || !r.share) toRun.emplace_back(v, st);
        }
    }
    return toRun;
}

// Rounds: share what can be shared; of the rest, resolve one variant per group of like
// structural values (every variant on its own in the last round), and repeat.
void resolveInRounds(Resolution& r, const std::vector<std::string>& stagePaths,
                     const std::vector<VariantChoice>& choices, const SourceReader& reader, int jobs) {
    for (int round = 0;; ++round) {
        const auto toRun = planRound(r, choices, round);
        if (toRun.empty()) break;
        runPool(toRun.size(), jobs, [&](std::size_t i) {
            const auto [v, st] = toRun[i];
            r.results[v][st] = resolveStage(stagePaths[st], r.options[v], reader);
            r.done[v][st] = 1;
        });
        for (const auto& [v, st] : toRun)
            r.reps[st].push_back(
                {&r.results[v][st], &r.options[v], r.share ? structureOf(r.results[v][st], reader) : std::nullopt});
    }
}

// Keys: a shared result has its representative's files and body, so the costly part
// (the body's signature, which define names the files meet) is worked out once per run.
void assignValidationKeys(Resolution& r, const SourceReader& reader, int jobs) {
    std::vector<std::pair<std::size_t, std::size_t>> all;
    for (std::size_t v = 0; v < r.results.size(); ++v)
        for (std::size_t st = 0; st < r.reps.size(); ++st) all.emplace_back(v, st);
    std::map<const Representative*, ValidationKeyBasis> bases;
    std::vector<const Representative*> needed;
    for (const auto& [v, st] : all)
        if (r.origin[v][st] && bases.try_emplace(r.origin[v][st]).second) needed.push_back(r.origin[v][st]);
    std::vector<std::string> names;
    if (!r.options.empty())
        for (const auto& d : r.options[0].defines) names.push_back(d.first);
    runPool(needed.size(), jobs, [&](std::size_t i) {
        const Representative* rep = needed[i];
        bases.at(rep) = validationKeyBasis(rep->result->stage, rep->options->defines.size(), names, reader);
    });
    runPool(all.size(), jobs, [&](std::size_t i) {
        const auto [v, st] = all[i];
        auto& stage = r.results[v][st].stage;
        stage.validationKey = r.origin[v][st] ? validationKey(stage, r.options[v].defines, bases.at(r.origin[v][st]))
                                              : validationKey(stage, r.options[v].defines, reader);
    });
}

}  // namespace

std::vector<std::vector<ResolveResult>> resolveVariants(const std::vector<std::string>& stagePaths,
                                                        const ResolveOptions& base,
                                                        const std::vector<VariantChoice>& choices,
                                                        const SourceReader& reader, int jobs,
                                                        const std::vector<ResolveResult>& baseRuns, bool share) {
    Resolution r = startResolution(stagePaths.size(), base, choices, baseRuns, share, reader);
    resolveInRounds(r, stagePaths, choices, reader, jobs);
    assignValidationKeys(r, reader, jobs);
    return std::move(r.results);
}

}  // namespace prism::shaderc
