// "Did you mean" hints: the one edit-distance rule shared by prism-shaderc's diagnostics
// (misspelled modules, functions, includes, contract names) and the runtime's errors
// (variant axes, mesh attributes), so that the tool and the runtime suggest the same name
// for the same typo. Header-only, CPU only.
//
// Usage (snippet: examples/snippets/catalog_did_you_mean.cpp):
//
//     #include "prism/catalog/did_you_mean.hpp"
//     std::vector<std::string> axes{"DIRECTIONAL_LIGHTS", "POINT_LIGHTS", "FOG"};
//     std::string hint = prism::catalog::didYouMean("DIRECTIONAL_LIGHT", axes);
//     // hint == " (did you mean 'DIRECTIONAL_LIGHTS'?)"; "" when nothing is close
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace prism::catalog {

// Levenshtein distance.
inline std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

// How far a typo may be from the name it meant: 1 + size / 3, and less than `name`'s size
// (so that a one-letter name never "means" every other one-letter name).
inline std::size_t typoDistance(std::string_view name) {
    return std::min<std::size_t>(1 + name.size() / 3, name.size() > 0 ? name.size() - 1 : 0);
}

// The candidate closest to `name` within `maxDistance`, never `name` itself; ties go to
// the alphabetically first; "" when none is that close.
inline std::string closestName(std::string_view name, const std::vector<std::string>& candidates,
                               std::size_t maxDistance) {
    std::string best;
    std::size_t bestDistance = maxDistance + 1;
    for (const auto& c : candidates) {
        if (c == name) continue;
        const std::size_t d = editDistance(name, c);
        if (d < bestDistance || (d == bestDistance && !best.empty() && c < best)) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

// The closest candidate within typoDistance(name).
inline std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
    return closestName(name, candidates, typoDistance(name));
}

// " (did you mean 'x'?)" with the closest candidate, or "".
inline std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    const std::string best = closestName(name, candidates);
    return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

// The names joined with ", " (for "known: a, b, c"); "(none)" when there are none.
inline std::string nameList(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "(none)" : out;
}

}  // namespace prism::catalog
