// libFuzzer harness: `#pragma prism variant` parsing, the merge of the axes of a
// shader's stages and the enumeration of its combinations under `--variant` filters.
// Input: the stage text, optionally followed by a line "//--filters" and one
// `--variant` spec per line (SHADER:NAME=VALUE,...; shader "main" or "*").
// Oracle: no crash, leak, undefined behaviour, hang or escaping exception; every choice
// sets each axis once, to one of its declared values.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <sstream>

#include "fuzz_input.hpp"
#include "include_resolver.hpp"
#include "variants.hpp"

using namespace prism::shaderc;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n//--filters\n", 2);
    MemoryReader files{
        {"main.frag", parts[0]},
        {"lib/lights.glsl", "#pragma prism variant DIRECTIONAL_LIGHTS 0 1 2 4\n#pragma prism variant FOG\n"}};
    ResolveOptions options;
    options.includeDirs = {"lib"};
    const ResolveResult stage = resolveStage("main.frag", options, files);
    const AxesResult axes = axesFromPragmas(stage.stage.variantPragmas);

    std::vector<std::string> specs;
    if (parts.size() > 1) {
        std::istringstream lines(parts[1]);
        for (std::string line; std::getline(lines, line);) specs.push_back(line);
    }
    const FilterParseResult filters = parseVariantFilters(specs);
    const ChoicesResult choices = variantChoices("main", axes.axes, filters.filters);
    for (const auto& choice : choices.choices) {
        if (choice.defines.size() != axes.axes.size()) std::abort();
        for (std::size_t a = 0; a < axes.axes.size(); ++a) {
            const auto& values = axes.axes[a].values;
            if (choice.defines[a].first != axes.axes[a].name ||
                std::find(values.begin(), values.end(), choice.defines[a].second) == values.end()) {
                std::fprintf(stderr, "choice %s sets axis %zu wrongly\n", choice.name.c_str(), a);
                std::abort();
            }
        }
    }
    return 0;
}
