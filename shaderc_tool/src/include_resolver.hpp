// Stage 2 of prism-shaderc: turns one stage file into a single driver-safe GLSL text.
//
// - `#include "x"` searches the including file's directory, then each include dir in
//   order; `#include <x>` searches only the include dirs.
// - Every file enters a stage at most once (identity = canonical path), so diamonds
//   work without guards; `#pragma once` is accepted and dropped.
// - An include cycle is an error printing the chain `a.glsl -> b.glsl -> a.glsl`.
// - A missing include is an error at the including file:line listing the dirs searched.
// - #if/#ifdef/#ifndef/#elif/#else/#endif are evaluated with the given defines plus
//   the #define/#undef seen so far, and an #include in an inactive branch is not
//   followed (the conditional lines themselves are kept for the compiler).
// - Output: `#version` on line 1 (the first #version found, else the default), then
//   `#define NAME VALUE` for every define, then the text with integer-only
//   `#line <line> <source-number>` directives; source 0 is the stage file, and
//   `files` maps numbers to paths. No GL_GOOGLE_* / ARB include extension lines.
// - `#pragma prism variant NAME [v1 v2 ...]` lines are collected and blanked.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct ResolvedFile {
    std::uint32_t number = 0;        // source-string number in #line directives
    std::string path;                // display path (as joined from the given paths)
    std::string canonical;           // identity key
    std::vector<IncludeSite> chain;  // includers, innermost first; empty for the stage file
};

// `#pragma prism variant NAME v1 v2 ...`; no values means a boolean axis {0, 1}.
struct VariantPragma {
    std::string name;
    std::vector<std::string> values;
    std::string file;
    int line = 0;
};

struct ResolvedStage {
    std::string text;              // the flattened, driver-safe GLSL
    std::string versionDirective;  // e.g. "#version 330 core"
    int versionNumber = 330;
    std::vector<ResolvedFile> files;  // index == source number
    std::vector<VariantPragma> variantPragmas;
    std::vector<std::string> filesRead;  // display paths of every file read, in order
};

struct ResolveOptions {
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;  // NAME, VALUE ("" -> defined empty)
    std::string defaultVersion = "#version 330 core";
};

struct ResolveResult {
    bool ok = false;
    ResolvedStage stage;
    std::vector<Diagnostic> diagnostics;  // errors make ok false; warnings may appear either way
};

ResolveResult resolveStage(const std::string& stagePath, const ResolveOptions& options, const SourceReader& reader);

// A module as the catalogue stores it: its own text with #include, #version and
// #pragma once lines blanked (so line numbers stay true), its leading comment as the
// description, and its direct includes (display paths) in order.
struct ModuleSource {
    std::string path;
    std::string canonical;
    std::string text;
    std::string description;
    std::vector<std::string> includes;
};

struct ModuleScanResult {
    bool ok = false;
    ModuleSource module;
    std::vector<Diagnostic> diagnostics;
};

ModuleScanResult scanModule(const std::string& modulePath, const ResolveOptions& options, const SourceReader& reader);

}  // namespace prism::shaderc
