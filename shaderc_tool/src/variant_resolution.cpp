// Parallel resolution of a shader's variants, sharing what cannot differ (see
// variant_resolution.hpp).
#include "variant_resolution.hpp"

#include <cctype>
#include <deque>
#include <map>
#include <optional>

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
    for (const auto& [name, value] : options.defines) head += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    r.stage.text = head + r.stage.text.substr(end);
    r.stage.shared = true;
    return r;
}

}  // namespace

std::vector<std::vector<ResolveResult>> resolveVariants(const std::vector<std::string>& stagePaths,
                                                        const ResolveOptions& base,
                                                        const std::vector<VariantChoice>& choices,
                                                        const SourceReader& reader, int jobs,
                                                        const std::vector<ResolveResult>& baseRuns, bool share) {
    const std::size_t variants = choices.size(), stages = stagePaths.size();
    std::vector<std::vector<ResolveResult>> results(variants, std::vector<ResolveResult>(stages));
    std::vector<ResolveOptions> options(variants, base);
    for (std::size_t v = 0; v < variants; ++v)
        options[v].defines.insert(options[v].defines.end(), choices[v].defines.begin(), choices[v].defines.end());
    std::vector<std::vector<char>> done(variants, std::vector<char>(stages, 0));
    std::vector<std::vector<const Representative*>> origin(variants, std::vector<const Representative*>(stages));
    std::vector<std::deque<Representative>> reps(stages);  // a deque: `origin` points into it
    if (share && baseRuns.size() == stages)
        for (std::size_t st = 0; st < stages; ++st)
            reps[st].push_back({&baseRuns[st], &base, structureOf(baseRuns[st], reader)});

    // Rounds: share what can be shared; of the rest, resolve one variant per group of
    // like structural values (every variant on its own in the last round), and repeat.
    for (int round = 0;; ++round) {
        std::vector<std::pair<std::size_t, std::size_t>> toRun;  // (variant, stage)
        for (std::size_t st = 0; st < stages; ++st) {
            std::map<std::vector<std::string>, bool> groupsTaken;
            for (std::size_t v = 0; v < variants; ++v) {
                if (done[v][st]) continue;
                bool shared = false;
                for (const auto& rep : reps[st]) {
                    if (share && mayShare(rep, options[v])) {
                        results[v][st] = withDefines(*rep.result, *rep.options, options[v]);
                        origin[v][st] = &rep;
                        done[v][st] = 1;
                        shared = true;
                        break;
                    }
                }
                if (shared) continue;
                // The group: the values of the macros that the first representative found
                // structural; the first variant alone when there is no representative yet;
                // each variant alone when the first has no structure, or from round 2 on.
                std::vector<std::string> group;
                if (share && reps[st].empty()) {
                    group.push_back("first");
                } else if (share && round < 2 && reps[st].front().structure) {
                    for (const auto& [name, value] : choices[v].defines)
                        group.push_back(reps[st].front().structure->decisive.contains(name) ? value : "\x01");
                } else {
                    group.push_back(std::to_string(v));
                }
                if (groupsTaken.try_emplace(group, true).second || !share) toRun.emplace_back(v, st);
            }
        }
        if (toRun.empty()) break;
        runPool(toRun.size(), jobs, [&](std::size_t i) {
            const auto [v, st] = toRun[i];
            results[v][st] = resolveStage(stagePaths[st], options[v], reader);
            done[v][st] = 1;
        });
        for (const auto& [v, st] : toRun)
            reps[st].push_back({&results[v][st], &options[v], share ? structureOf(results[v][st], reader) : std::nullopt});
    }

    // Keys: a shared result has its representative's files and body, so the costly part
    // (the body's signature, which define names the files meet) is worked out once per run.
    std::vector<std::pair<std::size_t, std::size_t>> all;
    for (std::size_t v = 0; v < variants; ++v)
        for (std::size_t st = 0; st < stages; ++st) all.emplace_back(v, st);
    std::map<const Representative*, ValidationKeyBasis> bases;
    std::vector<const Representative*> needed;
    for (const auto& [v, st] : all)
        if (origin[v][st] && bases.try_emplace(origin[v][st]).second) needed.push_back(origin[v][st]);
    std::vector<std::string> names;
    if (variants > 0)
        for (const auto& d : options[0].defines) names.push_back(d.first);
    runPool(needed.size(), jobs, [&](std::size_t i) {
        const Representative* rep = needed[i];
        bases.at(rep) = validationKeyBasis(rep->result->stage, rep->options->defines.size(), names, reader);
    });
    runPool(all.size(), jobs, [&](std::size_t i) {
        const auto [v, st] = all[i];
        auto& stage = results[v][st].stage;
        stage.validationKey = origin[v][st] ? validationKey(stage, options[v].defines, bases.at(origin[v][st]))
                                            : validationKey(stage, options[v].defines, reader);
    });
    return results;
}

}  // namespace prism::shaderc
