// Limits checked on every file before glslang's preprocessor reads it. glslang
// recurses once per '(' or unary operator of an #if expression (100,000 nested '('
// overflow its stack) and expands macros without a size cap (a 22-level chain of
// doubling macros is 4 million tokens), so prism-shaderc bounds both first:
//   - an #if/#elif expression, after macro expansion, has at most 10,000 tokens;
//   - one line's macros expand to at most 1,000,000 tokens;
//   - macro expansions (calls and macros inside macros) nest at most 256 deep.
// The expansion sizes are upper bounds: every #define of every file read so far
// counts, in any branch and even after an #undef, so an error never depends on
// which branch a file takes. (glslang's own limits, such as 65 nested #if groups,
// are reported by glslang.)
//
//   MacroSizeTable macros;
//   auto problems = checkPreprocessorLimits("a.glsl", splitLogicalLines(text), macros);
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "directive_lines.hpp"

namespace prism::shaderc {

struct PreprocessorLimits {
    std::uint64_t maxConditionTokens = 10'000;
    std::uint64_t maxLineTokens = 1'000'000;
    int maxCallNesting = 256;
};

// Every macro definition seen, for the size bounds (see above).
class MacroSizeTable {
  public:
    struct Definition {
        bool functionLike = false;
        std::vector<std::string> parameters;
        std::vector<std::string> body;  // tokens
    };

    // Reads the argument of a #define line; malformed ones are ignored (glslang reports them).
    void defineFromDirective(const std::string& argument);
    void define(const std::string& name, const std::string& value);
    const std::vector<Definition>* find(const std::string& name) const;
    std::size_t definitionCount() const { return definitionCount_; }  // every #define so far
    std::map<std::string, std::uint64_t>& objectSizeCache() const { return objectSizes_; }

  private:
    std::map<std::string, std::vector<Definition>> definitions_;
    mutable std::map<std::string, std::uint64_t> objectSizes_;  // cleared by every define
    std::size_t definitionCount_ = 0;
};

// Each file's #if/#ifdef/#ifndef ... #endif must balance on its own (as in C): an
// unterminated group is reported at its opening line, a stray #else/#elif/#endif at
// its own. This is lexical: no condition is evaluated.
std::vector<Diagnostic> checkConditionalStructure(const std::string& file, const std::vector<LogicalLine>& lines);

// Checks `lines` of `file` in order, adding its #defines to `macros` as it goes.
// Returns one error per line over a limit.
std::vector<Diagnostic> checkPreprocessorLimits(const std::string& file, std::span<const LogicalLine> lines,
                                                MacroSizeTable& macros, const PreprocessorLimits& limits = {});

}  // namespace prism::shaderc
