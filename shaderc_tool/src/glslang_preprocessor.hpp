// Decides which #includes (and #version / #pragma lines) of a stage are active by
// running glslang's own preprocessor on it, with an include callback that records
// what glslang actually includes, in order and with glslang's macro state. So the
// files prism-shaderc flattens into a stage are exactly the ones glslang would read:
// 32-bit #if arithmetic, glslang's predefined macros for the stage and version,
// function-like macros and comments all behave as in the compiler.
//
// The callback also applies prism-shaderc's include rules:
//   - search order: include_search.hpp; nesting deeper than 256 files is an error
//     naming the chain; an include another folder's file could answer is a warning;
//   - include-once: a file enters a stage once (identity = canonical path), so
//     unguarded diamonds work; `#pragma prism reinclude` in a file opts it out (X-macro
//     templates meant to be included again with other macros);
//   - cycles: re-entering a file that is still open is an error with its chain, unless
//     the file has an active `#pragma once` or an include guard (#ifndef G / #define G
//     ... #endif around the whole file) whose macro glslang has defined by then.
// Before glslang reads a file, preprocessor_limits.hpp bounds its #if expressions and
// macro expansions. glslang's preprocessor errors (#error, malformed #if, more than 65 nested
// #if groups ...) come back at the file's own line.
//
// How the lines are followed: each file is handed to glslang with its line count
// kept, `#include "x"` on line L rewritten as `#include "L:x"` and every #version,
// `#pragma once` and `#pragma prism` line as a probe `#include "L?"`, so the callback
// learns the line of every directive glslang reaches.
//
//   auto run = preprocessWithGlslang("s/a.frag", options, GlslVersion{330, "core"}, reader);
//   for (const auto& file : run.files) ...  // file.includes: line -> file it brought in
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "directive_lines.hpp"
#include "include_search.hpp"
#include "source_reader.hpp"
#include "spirv_env.hpp"
#include "target_rules.hpp"

namespace prism::shaderc {

constexpr int kMaxIncludeDepth = 256;

struct ResolveOptions {
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;  // NAME, VALUE ("" -> defined empty)
    std::string defaultVersion = "#version 330 core";
    std::string baseDir;  // where "/x" includes are also looked up; "" = nowhere else
    // An #include that another folder's file of the same name could answer is a warning
    // (shadowedIncludeMessage); module scans turn it off: the stages that include them report it.
    bool warnShadowedIncludes = true;
    // scanModule's "module has no leading comment" warning; the catalogue turns it off for
    // libraries found through -I outside --base-dir (--warn-undocumented-modules).
    bool warnUndocumentedModule = true;
    TargetRules rules = {};  // the client's (Options::rules): the Vulkan client's predefine VULKAN
};

// One file as glslang entered it.
struct EnteredFile {
    std::uint32_t number = 0;  // order of entry = source number in the flattened stage
    std::string display;
    std::string canonical;
    std::vector<IncludeSite> chain;  // includers, innermost first; empty for the top file
    std::vector<LogicalLine> lines;
    std::map<int, std::uint32_t> includes;  // first line of an #include -> the file it brought in
    std::set<int> reached;                  // first lines of the probed directives glslang reached
    std::vector<FoundFile> found;           // every file its active #includes named, in order, once
};

struct PreprocessRun {
    std::vector<EnteredFile> files;  // [0] = the top file; empty when it cannot be read
    std::vector<Diagnostic> diagnostics;
    bool ok = false;
};

// The macro G of an include guard around the whole file (`#ifndef G` or
// `#if !defined(G)`, then `#define G`, ... `#endif` last); "" when there is none.
std::string includeGuardOf(const std::vector<LogicalLine>& lines);

// glslang builds its built-in symbol tables once per process and #version, in the first
// run (every stage kind at once, behind a global lock). This runs it on an empty text,
// so --stats can show that cost apart; returns the milliseconds it took.
double buildGlslangBuiltIns(const GlslVersion& version);

// `version` is the one glslang is told to use (the stage's #version lines are probes).
PreprocessRun preprocessWithGlslang(const std::string& path, const ResolveOptions& options, const GlslVersion& version,
                                    const SourceReader& reader);

}  // namespace prism::shaderc
