// Variants: the axes a shader declares with `#pragma prism variant NAME [values...]`
// (no values = boolean 0/1) and the combinations to validate and emit, all of them or
// only those that `--variant SHADER:NAME=VALUE,...` asks for.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "include_resolver.hpp"

namespace prism::shaderc {

struct Axis {
    std::string name;
    std::vector<std::string> values;
};

struct VariantChoice {
    std::string name;  // "FOG=1,DIRECTIONAL_LIGHTS=4", or "default" without axes
    std::vector<std::pair<std::string, std::string>> defines;  // one per axis, axis order
};

// A parsed `--variant` option: shader name and the fixed axis values.
struct VariantFilter {
    std::string shader;
    std::vector<std::pair<std::string, std::string>> fixed;
};

struct AxesResult {
    std::vector<Axis> axes;
    std::vector<Diagnostic> diagnostics;
};

// Merges the pragmas of every stage of one shader (same name must mean same values).
AxesResult axesFromPragmas(const std::vector<VariantPragma>& pragmas);

struct FilterParseResult {
    std::vector<VariantFilter> filters;
    std::vector<Diagnostic> diagnostics;
};
FilterParseResult parseVariantFilters(const std::vector<std::string>& specs);

// Every combination (first axis varies slowest), restricted to the filters that name
// `shader` when there are any. Filters naming unknown axes or values are errors. A
// filter for shader "*" applies to every shader, with only the axes that shader declares
// (`--variant '*:DIRECTIONAL_LIGHTS=2'` builds just the two-light variants everywhere).
// More combinations than this (the product of the axes' value counts) is an error
// naming the shader, before any is enumerated (docs/reliability.md).
inline constexpr std::size_t kMaxVariantCombinations = 4096;

struct ChoicesResult {
    std::vector<VariantChoice> choices;
    std::vector<Diagnostic> diagnostics;
};
ChoicesResult variantChoices(const std::string& shader, const std::vector<Axis>& axes,
                             const std::vector<VariantFilter>& filters);

std::string variantName(const std::vector<std::pair<std::string, std::string>>& defines);

}  // namespace prism::shaderc
