// The one `#line` numbering rule of Prism, shared by prism-shaderc's resolver (which
// writes `#line` into flattened stages), its validator (which reads them back to find
// a token's column) and run-time composition (prism::gl::composeStage). glslang, the
// reference, numbers the line after `#line N` as N in GLSL ES (100, 300 es, ...) and in
// GLSL 3.30 and later, and as N + 1 in GLSL before 3.30
// (TParseContext::lineDirectiveShouldSetNextLine: `isEsProfile() || version >= 330`);
// tests/shaderc/test_line_directive.cpp checks this against glslang for #version 100,
// 300 es, 330 and 450. Header-only, CPU only.
//
// Usage (snippet: examples/snippets/catalog_line_directive.cpp):
//
//     #include "prism/catalog/line_directive.hpp"
//     const auto version = prism::catalog::glslVersionOf("#version 300 es");
//     // make the next line line 12 of source string 2:
//     std::string directive = prism::catalog::lineDirective(12, 2, version);  // "#line 12 2"
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace prism::catalog {

struct GlslVersionTag {
    int number = 0;   // 0 when unreadable
    bool es = false;  // GLSL ES: "#version 300 es", and "#version 100" (ES 1.00 has no profile word)
};

// Reads a `#version` directive ("#version 330 core", "#version 300 es", "  # version 100").
constexpr GlslVersionTag glslVersionOf(std::string_view directive) {
    GlslVersionTag tag;
    std::size_t p = directive.find_first_of("0123456789");
    if (p == std::string_view::npos) return tag;
    while (p < directive.size() && directive[p] >= '0' && directive[p] <= '9')
        tag.number = tag.number * 10 + (directive[p++] - '0');
    while (p < directive.size() && (directive[p] == ' ' || directive[p] == '\t')) ++p;
    const std::string_view profile = directive.substr(p);
    tag.es =
        tag.number == 100 ||
        (profile.size() >= 2 && profile.substr(0, 2) == "es" &&
         (profile.size() == 2 || profile[2] == ' ' || profile[2] == '\t' || profile[2] == '\r' || profile[2] == '\n'));
    return tag;
}

// True when the line after `#line N` is line N; false when it is line N + 1.
constexpr bool lineDirectiveNamesNextLine(GlslVersionTag version) {
    return version.es || version.number >= 330;
}

// The number of the line right after `#line n`.
constexpr int lineAfterDirective(int n, GlslVersionTag version) {
    return lineDirectiveNamesNextLine(version) ? n : n + 1;
}

// The `#line` directive (integer form, no newline) after which the next line is line
// `nextLine` of source string `source`.
inline std::string lineDirective(int nextLine, std::uint32_t source, GlslVersionTag version) {
    const int n = lineDirectiveNamesNextLine(version) ? nextLine : nextLine - 1;
    return "#line " + std::to_string(n) + " " + std::to_string(source);
}

}  // namespace prism::catalog
