// Part of stage 4 (catalog_builder.hpp): turns one stage file into a single driver-safe
// GLSL text.
//
// - Which #include, #version and #pragma lines are active is decided by glslang's own
//   preprocessor (glslang_preprocessor.hpp), with the -D and variant macros; that is
//   also where the include search, include-once, cycle and depth rules live.
// - Output: `#version` on line 1 (the first active #version, else the default), then
//   `#define NAME VALUE` for every define, then the text with each active #include
//   replaced by its file and integer-only `#line <line> <source-number>` directives;
//   source 0 is the stage file, and `files` maps numbers to paths. Conditionals stay
//   in the text for the compiler. No GL_GOOGLE_* / ARB include extension lines.
// - `#pragma prism variant NAME [v1 v2 ...]` and `#pragma prism targets T...` lines are
//   collected and blanked.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "glslang_preprocessor.hpp"
#include "prism/shaderc/build_step.hpp"
#include "source_reader.hpp"
#include "targets.hpp"

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

// `#pragma prism targets gl spirv`: the only targets the stage serves (targets.hpp).
struct TargetsPragma {
    std::vector<Target> targets;
    std::string file;
    int line = 0;
};

struct ResolvedStage {
    std::string text;              // the flattened, driver-safe GLSL
    std::string versionDirective;  // e.g. "#version 330 core"
    int versionNumber = 330;
    std::vector<ResolvedFile> files;  // index == source number
    std::vector<VariantPragma> variantPragmas;
    std::optional<TargetsPragma> targetsPragma;  // none: the stage serves every target
    std::vector<std::string> filesRead;          // display paths of every file read, in order
    std::string validationKey;                   // what the compiler sees (validation_key.hpp), set by resolveVariants
    bool shared = false;                         // copied from another variant's run (variant_resolution.hpp)
};

struct ResolveResult {
    bool ok = false;
    ResolvedStage stage;
    std::vector<Diagnostic> diagnostics;  // errors make ok false; warnings may appear either way
};

// `reader` is injectable (MemoryReader) so tests and fuzzers run on in-memory files.
ResolveResult resolveStage(const std::string& stagePath, const ResolveOptions& options, const SourceReader& reader);

// A module as the catalogue stores it: its own text with #include and #pragma once
// lines blanked (so line numbers stay true; a #version line is kept), its leading comment as the
// description, and the files its active includes name (display paths) in order, as
// glslang's preprocessor sees the module on its own with the -D macros. The public API's
// ModuleText (prism/shaderc/build_step.hpp).
using ModuleSource = ModuleText;

struct ModuleScanResult {
    bool ok = false;
    ModuleSource module;
    std::vector<Diagnostic> diagnostics;
};

ModuleScanResult scanModule(const std::string& modulePath, const ResolveOptions& options, const SourceReader& reader);

}  // namespace prism::shaderc
