// The small part of a GLSL preprocessor the include resolver needs to decide which
// lines are active: splitting text into logical lines (continuations spliced,
// comments removed), recognising directives, a macro table, the `#if` expression
// evaluator and the #if/#ifdef/#ifndef/#elif/#else/#endif stack.
#pragma once

#include <cstdint>
#include <map>
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

bool isIdentifier(std::string_view text);
std::string_view trim(std::string_view text);
std::vector<std::string> splitWhitespace(std::string_view text);

struct Macro {
    std::string value;  // the replacement text, trimmed
    bool functionLike = false;
};

// Macros known at a point of the text: predefined, given with -D, and #define'd.
class MacroTable {
  public:
    void define(const std::string& name, std::string value, bool functionLike = false);
    void undefine(const std::string& name);
    bool isDefined(const std::string& name) const;
    const Macro* find(const std::string& name) const;
    // Reads the argument of a `#define` line (`NAME value` or `NAME(args) body`).
    // Returns an error message, empty on success.
    std::string defineFromDirective(std::string_view argument);

  private:
    std::map<std::string, Macro, std::less<>> macros_;
};

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

// Defines __VERSION__ and GL_core_profile / GL_compatibility_profile / GL_ES like a
// GLSL compiler does for `version`.
void predefineVersionMacros(MacroTable& macros, const GlslVersion& version);

struct ConditionValue {
    std::int64_t value = 0;
    std::string error;  // non-empty when the expression could not be evaluated
    bool ok() const { return error.empty(); }
};

// Evaluates the expression of an #if / #elif: integer literals (decimal, hex, octal,
// optional u suffix), `defined X`, `defined(X)`, object-like macros (expanded
// recursively), undefined identifiers as 0, and the C operators incl. `?:`.
ConditionValue evaluateCondition(std::string_view expression, const MacroTable& macros);

bool isConditionalDirective(std::string_view name);

// The nesting of conditional groups in one file.
class ConditionalStack {
  public:
    struct OpenGroup {
        std::string directive;  // "if", "ifdef" or "ifndef"
        int line = 0;
    };

    // Applies one conditional directive found at `line`. Conditions are evaluated
    // only where they matter (not inside inactive groups, not after a taken branch).
    // Returns an error message, empty on success; the stack stays consistent either way.
    std::string apply(const Directive& directive, int line, const MacroTable& macros);

    // True when lines at this point are compiled.
    bool active() const;
    // The innermost group still open (for "unterminated #if" at the end of a file).
    std::optional<OpenGroup> innermostOpen() const;

  private:
    struct Group {
        OpenGroup opened;
        bool parentActive = true;
        bool branchTaken = false;  // some branch of this group was already active
        bool active = false;
        int elseLine = 0;  // line of its #else, 0 when none yet
    };

    std::string openGroup(const Directive& directive, int line, const MacroTable& macros);
    std::string elif (const Directive& directive, const MacroTable& macros);
    std::string elseBranch(int line);
    std::string endGroup();

    std::vector<Group> groups_;
};

}  // namespace prism::shaderc
