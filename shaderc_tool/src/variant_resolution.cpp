// Parallel resolution of a shader's variants, sharing what cannot differ (see
// variant_resolution.hpp).
#include "variant_resolution.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include "job_pool.hpp"

namespace prism::shaderc {
namespace {

void addIdentifiers(std::string_view text, std::set<std::string>& out) {
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (std::isalpha(c) || c == '_') {
            std::size_t j = i + 1;
            while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
            out.emplace(text.substr(i, j - i));
            i = j;
        } else {
            ++i;
        }
    }
}

// Every identifier the preprocessor could meet in a run that read `filesRead` with
// `options` (the files' texts and the macros' values); nullopt when a file pastes
// tokens (`##` can make a macro name that appears nowhere).
std::optional<std::set<std::string>> identifiersSeen(const ResolvedStage& stage, const ResolveOptions& options,
                                                     const SourceReader& reader) {
    std::set<std::string> ids;
    for (const auto& path : stage.filesRead) {
        const auto text = reader.read(path);
        if (!text || text->find("##") != std::string::npos) return std::nullopt;
        addIdentifiers(*text, ids);
    }
    for (const auto& [name, value] : options.defines) addIdentifiers(value, ids);
    return ids;
}

// `from`'s result for another variant whose defines differ only in macros the run
// never met: the same files and decisions; only the #define block at the top differs.
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
                                                        const SourceReader& reader, int jobs) {
    const std::size_t variants = choices.size(), stages = stagePaths.size();
    std::vector<std::vector<ResolveResult>> results(variants, std::vector<ResolveResult>(stages));
    std::vector<ResolveOptions> options(variants, base);
    for (std::size_t v = 0; v < variants; ++v)
        options[v].defines.insert(options[v].defines.end(), choices[v].defines.begin(), choices[v].defines.end());
    std::vector<std::vector<char>> done(variants, std::vector<char>(stages, 0));
    auto resolve = [&](std::size_t v, std::size_t st) {
        results[v][st] = resolveStage(stagePaths[st], options[v], reader);
        done[v][st] = 1;
    };
    const bool share = !std::getenv("PRISM_SHADERC_NO_VARIANT_SHARING") && variants > 1;

    // 1. The first variant of every stage, for real.
    runPool(stages, jobs, [&](std::size_t st) { resolve(0, st); });
    if (!share) {
        std::vector<std::pair<std::size_t, std::size_t>> rest;
        for (std::size_t v = 1; v < variants; ++v)
            for (std::size_t st = 0; st < stages; ++st) rest.emplace_back(v, st);
        runPool(rest.size(), jobs, [&](std::size_t i) { resolve(rest[i].first, rest[i].second); });
        return results;
    }

    // 2. Per stage, variants agreeing on the axes that run met form a group; each group's
    //    first member is resolved for real.
    std::vector<std::vector<std::size_t>> groupOf(stages, std::vector<std::size_t>(variants, 0));
    std::vector<std::pair<std::size_t, std::size_t>> representatives;  // (variant, stage) to resolve
    for (std::size_t st = 0; st < stages; ++st) {
        const auto seen = results[0][st].diagnostics.empty()
                              ? identifiersSeen(results[0][st].stage, options[0], reader)
                              : std::nullopt;
        std::map<std::vector<std::string>, std::size_t> firstWithKey;
        for (std::size_t v = 0; v < variants; ++v) {
            std::vector<std::string> key;
            for (const auto& [name, value] : choices[v].defines)
                key.push_back(!seen || seen->contains(name) ? value : std::string("\x01"));
            const auto [it, fresh] = firstWithKey.try_emplace(key, v);
            groupOf[st][v] = it->second;
            if (fresh && v != 0) representatives.emplace_back(v, st);
        }
    }
    runPool(representatives.size(), jobs,
            [&](std::size_t i) { resolve(representatives[i].first, representatives[i].second); });

    // 3. A member shares its representative's result when the macros in which they differ
    //    appear nowhere in what the representative's run read; otherwise it runs itself.
    std::vector<std::pair<std::size_t, std::size_t>> own;
    for (std::size_t st = 0; st < stages; ++st) {
        std::map<std::size_t, std::optional<std::set<std::string>>> seenOf;
        for (std::size_t v = 0; v < variants; ++v) {
            if (done[v][st]) continue;
            const std::size_t rep = groupOf[st][v];
            const ResolveResult& r = results[rep][st];
            auto it = seenOf.find(rep);
            if (it == seenOf.end())
                it = seenOf.emplace(rep, r.diagnostics.empty() ? identifiersSeen(r.stage, options[rep], reader)
                                                               : std::nullopt)
                         .first;
            bool shareable = it->second.has_value();
            for (std::size_t a = 0; shareable && a < choices[v].defines.size(); ++a)
                if (choices[v].defines[a].second != choices[rep].defines[a].second &&
                    it->second->contains(choices[v].defines[a].first))
                    shareable = false;
            if (shareable) {
                results[v][st] = withDefines(r, options[rep], options[v]);
                done[v][st] = 1;
            } else {
                own.emplace_back(v, st);
            }
        }
    }
    runPool(own.size(), jobs, [&](std::size_t i) { resolve(own[i].first, own[i].second); });
    return results;
}

}  // namespace prism::shaderc
