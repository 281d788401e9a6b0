// Variant axes, --variant filters and the enumeration of combinations.
#include "variants.hpp"

#include <algorithm>

namespace prism::shaderc {

std::string variantName(const std::vector<std::pair<std::string, std::string>>& defines) {
    if (defines.empty()) return "default";
    std::string s;
    for (const auto& [n, v] : defines) s += (s.empty() ? "" : ",") + n + "=" + v;
    return s;
}

AxesResult axesFromPragmas(const std::vector<VariantPragma>& pragmas) {
    AxesResult r;
    std::vector<const VariantPragma*> firstSeen;
    for (const auto& p : pragmas) {
        auto values = p.values.empty() ? std::vector<std::string>{"0", "1"} : p.values;
        auto it = std::find_if(r.axes.begin(), r.axes.end(), [&](const Axis& a) { return a.name == p.name; });
        if (it == r.axes.end()) {
            r.axes.push_back({p.name, values});
            firstSeen.push_back(&p);
        } else if (it->values != values) {
            const auto* first = firstSeen[static_cast<std::size_t>(it - r.axes.begin())];
            auto d = makeError(p.file, p.line, 1,
                               "variant '" + p.name +
                                   "' is declared again with other values; declare it once "
                                   "or with the same values everywhere");
            d.notes.push_back({Severity::Note, first->file, first->line, 1, "first declared here", {}, {}});
            r.diagnostics.push_back(std::move(d));
        }
    }
    return r;
}

FilterParseResult parseVariantFilters(const std::vector<std::string>& specs) {
    FilterParseResult r;
    for (const auto& spec : specs) {
        auto colon = spec.find(':');
        if (colon == std::string::npos || colon == 0) {
            r.diagnostics.push_back(
                makeError("", 0, 0, "--variant " + spec + ": expected SHADER:NAME=VALUE[,NAME=VALUE...]"));
            continue;
        }
        VariantFilter f{spec.substr(0, colon), {}};
        std::string rest = spec.substr(colon + 1);
        std::size_t start = 0;
        bool ok = true;
        while (start <= rest.size() && !rest.empty()) {
            auto comma = rest.find(',', start);
            std::string item = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            auto eq = item.find('=');
            if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
                ok = false;
                break;
            }
            f.fixed.emplace_back(item.substr(0, eq), item.substr(eq + 1));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        if (!ok) {
            r.diagnostics.push_back(
                makeError("", 0, 0, "--variant " + spec + ": expected SHADER:NAME=VALUE[,NAME=VALUE...]"));
            continue;
        }
        r.filters.push_back(std::move(f));
    }
    return r;
}

namespace {

bool matches(const VariantFilter& f, const std::vector<std::pair<std::string, std::string>>& defines) {
    for (const auto& fixed : f.fixed) {  // no structured bindings: Clang 14 cannot capture them
        auto it = std::find_if(defines.begin(), defines.end(), [&](const auto& d) { return d.first == fixed.first; });
        if (it == defines.end() || it->second != fixed.second) return false;
    }
    return true;
}

}  // namespace

ChoicesResult variantChoices(const std::string& shader, const std::vector<Axis>& axes,
                             const std::vector<VariantFilter>& filters) {
    ChoicesResult r;
    std::vector<VariantFilter> mine;
    for (const auto& f : filters) {
        if (f.shader == "*") {  // every shader: only the axes it declares
            VariantFilter own{shader, {}};
            for (const auto& fixed : f.fixed)
                if (std::any_of(axes.begin(), axes.end(), [&](const Axis& a) { return a.name == fixed.first; }))
                    own.fixed.push_back(fixed);
            mine.push_back(std::move(own));
            continue;
        }
        if (f.shader != shader) continue;
        for (const auto& fixed : f.fixed) {  // no structured bindings: Clang 14 cannot capture them
            const std::string& name = fixed.first;
            const std::string& value = fixed.second;
            auto ax = std::find_if(axes.begin(), axes.end(), [&](const Axis& a) { return a.name == name; });
            if (ax == axes.end())
                r.diagnostics.push_back(makeError(
                    "", 0, 0, "--variant " + shader + ": shader '" + shader + "' declares no variant '" + name + "'"));
            else if (std::find(ax->values.begin(), ax->values.end(), value) == ax->values.end())
                r.diagnostics.push_back(
                    makeError("", 0, 0, "--variant " + shader + ": '" + name + "' has no value '" + value + "'"));
        }
        mine.push_back(f);
    }
    if (!r.diagnostics.empty()) return r;
    std::size_t combinations = 1;  // checked before enumerating: 40 boolean axes would never finish
    for (const auto& axis : axes) {
        combinations *= std::max<std::size_t>(axis.values.size(), 1);
        if (combinations > kMaxVariantCombinations) {
            r.diagnostics.push_back(makeError("", 0, 0,
                                              "shader '" + shader + "' declares more than " +
                                                  std::to_string(kMaxVariantCombinations) +
                                                  " variant combinations (the limit); declare fewer axes or values"));
            return r;
        }
    }

    std::vector<std::size_t> index(axes.size(), 0);
    while (true) {
        std::vector<std::pair<std::string, std::string>> defines;
        for (std::size_t a = 0; a < axes.size(); ++a) defines.emplace_back(axes[a].name, axes[a].values[index[a]]);
        bool wanted = mine.empty() || std::any_of(mine.begin(), mine.end(),
                                                  [&](const VariantFilter& f) { return matches(f, defines); });
        if (wanted) r.choices.push_back({variantName(defines), defines});
        // Odometer increment, last axis fastest.
        std::size_t a = axes.size();
        while (a > 0) {
            --a;
            if (++index[a] < axes[a].values.size()) break;
            index[a] = 0;
            if (a == 0) return r;
        }
        if (axes.empty()) return r;
    }
}

}  // namespace prism::shaderc
