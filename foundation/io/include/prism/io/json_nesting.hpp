// A nesting-depth check for JSON text, run before parsing so that a deeply nested input
// is a clear error instead of a stack overflow in the parser (docs/reliability.md), and the
// line and column of a byte offset, for the `file:line:col:` of a JSON error. Used by the
// binding-contract and scene loaders (header-only, CPU only).
//
// Usage (snippet: examples/snippets/io_json_nesting.cpp):
//
//     #include "prism/io/json_nesting.hpp"
//     auto at = prism::io::firstTooDeep(R"({"a": [[1]]})", 2);     // offset 7: the second '['
//     auto [line, column] = prism::io::lineColumnAt("{\n  [", 4);  // 2, 3: the '['
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace prism::io {

// Byte offset of the first '[' or '{' nested deeper than `maxDepth` (strings and their
// escapes skipped), or nullopt.
inline std::optional<std::size_t> firstTooDeep(std::string_view text, int maxDepth) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (ch == '\\')
                escaped = true;
            else if (ch == '"')
                inString = false;
        } else if (ch == '"') {
            inString = true;
        } else if (ch == '[' || ch == '{') {
            if (++depth > maxDepth) return i;
        } else if (ch == ']' || ch == '}') {
            --depth;
        }
    }
    return std::nullopt;
}

// 1-based line and column of a position in a text.
struct LineColumn {
    int line = 1;
    int column = 1;
};

// The line and column of the byte at 0-based `offset` (an offset past the end: the position
// after the last byte). nlohmann::json's parse_error::byte counts from 1: pass byte - 1.
inline LineColumn lineColumnAt(std::string_view text, std::size_t offset) {
    LineColumn at;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

}  // namespace prism::io
