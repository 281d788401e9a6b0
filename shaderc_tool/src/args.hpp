// Stage 1 of prism-shaderc: the command line, parsed into Options (CLI11).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "spirv_env.hpp"
#include "target_rules.hpp"
#include "targets.hpp"

namespace prism::shaderc {

struct Options {
    std::vector<std::string> inputs;                           // stage files or directories
    std::vector<std::string> includeDirs;                      // -I, searched in order
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=VALUE]
    std::vector<std::string> contracts;                        // --contract (JSON), merged in order
    std::vector<std::string> variantFilters;                   // --variant SHADER:NAME=V,NAME=V
    std::vector<std::string> programs;                         // --program NAME=FILE[,FILE...]
    std::string output;                                        // -o header
    std::string depfile;                                       // --depfile
    std::string stamp;                                         // --stamp: touched on every successful run
    std::string emitGlslDir;                                   // --emit-glsl
    std::string baseDir;                                       // --base-dir: embedded paths are relative to it
    std::string cacheDir;           // --cache-dir: validation results cache ("" = default, "none" = off)
    std::string nameSpace;          // --namespace; default: the header's file name (defaultNamespace)
    std::string client = "opengl";  // --client opengl|vulkan
    std::string targetEnv;          // --target-env (vulkan client only; "" = vulkan1.2)
    TargetRules rules;              // the client's, decided here once from --client and --target-env
    std::string emitSpirvDir;       // --emit-spirv: <program>[.<variant>].<stage>.spv
    std::string emitWeb;            // --emit-web: the web catalogue, a plain script (web_writer.hpp)
    std::string emitReflection;     // --emit-reflection: the SPIR-V's layout as JSON (reflection_writer.hpp)
    // --target gl,es300,spirv (targets.hpp). A Vulkan-client catalogue's output is SPIR-V
    // already: there --target may only say spirv, and `targets` stays {Gl}, the client's own.
    std::vector<Target> targets = {Target::Gl};
    int glslVersion = 330;
    std::string glslProfile = "core";
    ErrorFormat errorFormat = ErrorFormat::Gcc;
    int jobs = 0;                   // 0 = hardware concurrency
    bool printStats = false;        // --stats: how many programs were validated, shared, or found in the cache
    bool checkOnly = false;         // --check: no header; --emit-glsl, --depfile, --stamp are still written
    bool revalidate = false;        // --revalidate: --check does not ask the run record (up_to_date.hpp)
    bool noVariantSharing = false;  // --no-variant-sharing: every variant runs the preprocessor (the reference)
    // --warn-undocumented-modules all: also warn about modules of -I libraries outside --base-dir
    bool warnUndocumentedLibraryModules = false;
};

struct ArgsResult {
    std::optional<Options> options;  // empty: exit with `exitCode` (help, version, usage error)
    int exitCode = 0;
};

ArgsResult parseArgs(int argc, char** argv);

// The name of every option the parser knows ("-o", "--emit-web", "inputs", "--help"): each
// has its row in output_options.hpp (test_option_classes.cpp).
std::vector<std::string> commandLineOptionNames();

}  // namespace prism::shaderc
