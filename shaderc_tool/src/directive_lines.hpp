// The lexical part of GLSL preprocessing that prism-shaderc does itself: splitting a
// text into logical lines (continuations spliced, comments blanked), recognising
// directives and reading `#version`. Which lines are active is decided by glslang's
// own preprocessor (glslang_preprocessor.hpp), never here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace prism::shaderc {

// One logical line: physical lines joined by a trailing backslash.
struct LogicalLine {
    int firstLine = 1;                  // 1-based number of its first physical line
    std::vector<std::string> physical;  // the physical lines as written, without line endings
    std::string code;                   // spliced text with every comment replaced by spaces
    bool startsInComment = false;       // begins inside a /* */ block from an earlier line
    bool endsInComment = false;         // ends inside a /* */ block that goes on below
};

// Splits `text` (LF or CRLF, trailing newline optional) into logical lines, tracking
// /* */ comments across lines. An empty text has no lines.
std::vector<LogicalLine> splitLogicalLines(std::string_view text);

struct Directive {
    std::string name;      // "include", "if", "pragma", ...; empty for a lone '#'
    std::string argument;  // the rest of the line, trimmed, comments removed
};

// The directive on `line`, or nullopt when the line is not a preprocessor directive.
std::optional<Directive> parseDirective(const LogicalLine& line);

// The physical lines that replace a directive line dropped from the output: empty,
// except that the end of a comment begun on an earlier line ("... */" before the '#')
// is kept and a comment that goes on below is reopened (" /*"), so the lines around
// stay what they were.
std::vector<std::string> blankedDirective(const LogicalLine& line);

bool isIdentifier(std::string_view text);
// Position of `word` in `text` as a whole identifier (not inside a longer one), or npos.
std::size_t findWord(std::string_view text, std::string_view word);
// Directives whose words glslang takes as written, never macro-expanded: #pragma,
// #extension, #version and #error.
bool expandsNoMacros(const Directive& directive);
std::string_view trim(std::string_view text);
std::vector<std::string> splitWhitespace(std::string_view text);

// The version a `#version` line asks for.
struct GlslVersion {
    int number = 0;
    std::string profile;  // as written: "", "core", "compatibility" or "es"

    bool isEs() const { return profile == "es" || number == 100; }
    // The profile the compiler will use ("core" when none is written for >= 150).
    std::string effectiveProfile() const;
    std::string directive() const;  // "#version 330 core"
    bool sameAs(const GlslVersion& other) const;
};

// Parses the argument of a `#version` line ("330 core"); nullopt when malformed.
std::optional<GlslVersion> parseVersionArgument(std::string_view argument);
// Parses a whole directive line ("#version 330 core").
std::optional<GlslVersion> parseVersionDirective(std::string_view line);

}  // namespace prism::shaderc
