// Command-line parsing for prism-shaderc (see docs/shaderc.md for the contract).
#include "args.hpp"
#include "data_file_records.hpp"
#include "module_naming.hpp"
#include "source_reader.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <thread>

namespace prism::shaderc {
namespace {

std::pair<std::string, std::string> splitDefine(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos) return {text, "1"};
    return {text.substr(0, eq), text.substr(eq + 1)};
}

bool isIdentifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (char c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

// The namespace of a header written without --namespace: its file name as an identifier
// (-o gen/toon_shaders.hpp: toon_shaders). prism_add_shaders(toon_shaders) names its header
// toon_shaders.hpp and its namespace toon_shaders, so the tool run by hand agrees with it,
// and no default is Prism's own prism::shaders, whose kCatalog a second catalogue would clash with.
std::string defaultNamespace(const std::string& header) {
    return cppIdentifier(std::filesystem::path(header).stem().string());
}

// A usage error: printed on stderr, exit status 2.
ArgsResult usageError(const std::string& message) {
    std::cerr << "prism-shaderc: error: " << message << "\n";
    return {std::nullopt, 2};
}

// A Vulkan-client catalogue's output is SPIR-V: --target (`given` as `list`) may say spirv,
// the same thing, so `targets` stays the client's own {Gl}; gl and es300 are OpenGL text.
std::string vulkanClientTargets(Options& o, bool given, const std::string& list) {
    if (o.client != "vulkan") return {};
    if (given && o.targets != std::vector<Target>{Target::Spirv})
        return "--target " + list +
               " with --client vulkan: a Vulkan-client catalogue's output is SPIR-V (its GLSL is Vulkan GLSL, "
               "neither OpenGL nor ES text); drop --target or give --target spirv, or build OpenGL-style "
               "sources with --client opengl --target " +
               list;
    o.targets = {Target::Gl};
    return {};
}

// Flag combinations where a flag would be ignored are refused, naming both flags;
// "" when the combination does what it says.
std::string conflictOf(const Options& o, const CLI::App& app) {
    if (o.checkOnly && !o.output.empty())
        return "--check writes no header, but -o " + o.output +
               " asks for one; drop --check (a run with -o validates too) or drop -o";
    if (o.revalidate && !o.checkOnly)
        return "--revalidate only changes --check (a run with -o validates what its inputs need); add --check or "
               "drop --revalidate";
    if (!o.depfile.empty() && o.stamp.empty() && o.output.empty())
        return "--depfile " + o.depfile + " needs a target to name: give --stamp <file> or -o <header>";
    if (app.count("--namespace") > 0 && o.output.empty())
        return "--namespace only names the generated header's namespace, and no header is written: give -o "
               "<header> or drop --namespace";
    if (o.client != "vulkan" && !o.targetEnv.empty())
        return "--target-env " + o.targetEnv + " picks a Vulkan version, and --client is " + o.client +
               "; add --client vulkan or drop --target-env";
    if (o.client != "vulkan" && !o.emitSpirvDir.empty() && !hasTarget(o.targets, Target::Spirv))
        return "--emit-spirv " + o.emitSpirvDir +
               " writes SPIR-V, and this run makes none; add the spirv target (--target gl,spirv), or --client "
               "vulkan for Vulkan GLSL, or drop --emit-spirv";
    if (!o.emitWeb.empty() && !hasTarget(o.targets, Target::Es300))
        return "--emit-web " + o.emitWeb +
               " writes the es300 (GLSL ES 3.00) texts for WebGL2, and this run makes none; add es300 to --target "
               "(--target gl,es300) or drop --emit-web";
    if (o.client != "vulkan" && !o.emitReflection.empty() && !hasTarget(o.targets, Target::Spirv))
        return "--emit-reflection " + o.emitReflection +
               " writes the SPIR-V's layout, and this run makes none; add the spirv target (--target gl,spirv), or "
               "--client vulkan for Vulkan GLSL, or drop --emit-reflection";
    if (!o.checkOnly && o.output.empty() && o.emitGlslDir.empty() && o.emitSpirvDir.empty() && o.emitWeb.empty() &&
        o.emitReflection.empty())
        return "nothing to write: give -o <header>, --emit-glsl <dir>, --emit-spirv <dir>, --emit-web <file.js>, "
               "--emit-reflection <file.json> or --check";
    if (!o.checkOnly && !o.output.empty() && o.emitGlslDir.empty() && dataPathFor(o.output) == o.output)
        return "-o " + o.output + ": the data file would overwrite the header; name the header .hpp or .h";
    return {};
}

// Every option, bound to `o` (to `defines`, `errfmt`, `warnUndocumented` and `targets`
// where parseArgs checks or converts them after).
void addOptions(CLI::App& app, Options& o, std::vector<std::string>& defines, std::string& errfmt,
                std::string& warnUndocumented, std::string& targets) {
    app.set_version_flag("--version", std::string("prism-shaderc ") + PRISM_VERSION);
    // Unknown options are collected (not an error inside CLI11, whose required-positional
    // check would otherwise speak first) and named below.
    app.allow_extras();
    app.add_option("inputs", o.inputs,
                   "shader stage files (.vert .tesc .tese .geom .frag .comp) or directories; same-name files "
                   "make one program");
    app.add_option("-I", o.includeDirs, "module search directory (repeatable, searched in order)")
        ->allow_extra_args(false);
    app.add_option("-o", o.output, "generated C++ header");
    app.add_option("--depfile", o.depfile, "Make-style depfile listing every file read (target: --stamp, else -o)");
    app.add_option("--stamp", o.stamp, "file touched on every successful run (build-system output)");
    app.add_option("--emit-glsl", o.emitGlslDir,
                   "also write each flattened stage as DIR/<shader>[.<variant>].<stage> (with --check too)");
    app.add_option("--client", o.client, "GLSL for opengl (driver GLSL, the default) or vulkan (SPIR-V, as glslc)")
        ->check(CLI::IsMember({"opengl", "vulkan"}))
        ->capture_default_str();
    app.add_option("--target-env", o.targetEnv,
                   "with --client vulkan: vulkan1.0, vulkan1.1, vulkan1.2 (default), vulkan1.3");
    app.add_option("--target", targets,
                   "what to produce and validate: a comma list of gl, es300 (GLSL ES 3.00), spirv (docs/targets.md)")
        ->capture_default_str();
    app.add_option("--emit-spirv", o.emitSpirvDir,
                   "with --client vulkan or --target spirv: also write each stage's SPIR-V as "
                   "DIR/<shader>[.<variant>].<stage>.spv (with --check too)");
    app.add_option("--emit-web", o.emitWeb,
                   "with es300 among --target: also write the web catalogue FILE.js, a plain script for WebGL2 "
                   "pages (docs/targets.md, \"Web catalogue\"; with --check too)");
    app.add_option("--emit-reflection", o.emitReflection,
                   "with --client vulkan or --target spirv: also write the SPIR-V's layout (descriptors, push "
                   "constants, vertex inputs, specialisation constants) as FILE.json (docs/targets.md, "
                   "\"Reflection\"; with --check too)");
    app.add_flag("--check", o.checkOnly, "validate only: no header (--emit-glsl, --depfile, --stamp still written)");
    app.add_option("-D", defines, "define a macro for every stage: NAME[=VALUE]")->allow_extra_args(false);
    app.add_option("--glsl-version", o.glslVersion, "default #version when a shader has none")->capture_default_str();
    app.add_option("--namespace", o.nameSpace,
                   "C++ namespace of the generated code (needs -o; default: the header's file name, "
                   "toon_shaders for -o gen/toon_shaders.hpp, as prism_add_shaders names it after its target)");
    app.add_option("--contract", o.contracts, "binding contract JSON (attributes and uniforms the runtime provides)")
        ->allow_extra_args(false);
    app.add_option("--variant", o.variantFilters,
                   "emit only this variant of a shader: SHADER:NAME=VALUE,NAME=VALUE (repeatable)")
        ->allow_extra_args(false);
    app.add_option("--program", o.programs,
                   "declare a program from any stage files, in any order: NAME=FILE[,FILE...] (repeatable; a file "
                   "may serve several programs)")
        ->allow_extra_args(false);
    app.add_option("--base-dir", o.baseDir, "paths embedded in the header are made relative to this directory");
    app.add_option("--errfmt", errfmt, "diagnostic format")->check(CLI::IsMember({"gcc", "msvc"}));
    app.add_option("-j", o.jobs, "parallel jobs (default: all cores)")->check(CLI::NonNegativeNumber);
    app.add_flag("--stats", o.printStats, "print how many programs were validated, shared or found in the cache");
    app.add_flag("--revalidate", o.revalidate,
                 "with --check: resolve and validate even when no code changed since the last clean check");
    app.add_flag("--no-variant-sharing", o.noVariantSharing,
                 "resolve every variant on its own (the reference that variant sharing must equal; same outputs)");
    app.add_option("--warn-undocumented-modules", warnUndocumented,
                   "which modules without a leading comment get a warning: 'project' (not those of -I folders "
                   "outside --base-dir) or 'all'")
        ->check(CLI::IsMember({"project", "all"}))
        ->capture_default_str();
    app.add_option("--cache-dir", o.cacheDir,
                   "validation results cache (content-addressed); default: next to --stamp, none without "
                   "--stamp; 'none' disables it");
}

}  // namespace

std::vector<std::string> commandLineOptionNames() {
    Options o;
    std::vector<std::string> defines;
    std::string errfmt, warnUndocumented, targets;
    CLI::App app;
    addOptions(app, o, defines, errfmt, warnUndocumented, targets);
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) names.push_back(option->get_name());
    return names;
}

ArgsResult parseArgs(int argc, char** argv) {
    Options o;
    std::vector<std::string> defines;
    std::string errfmt = "gcc";
    std::string warnUndocumented = "project";
    std::string targets = "gl";
    CLI::App app{"prism-shaderc: resolve #includes, validate GLSL with glslang and embed it in a C++ header",
                 "prism-shaderc"};
    addOptions(app, o, defines, errfmt, warnUndocumented, targets);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return {std::nullopt, e.get_exit_code() == 0 ? 0 : (code == 0 ? 0 : 2)};
    }
    for (const auto& extra : app.remaining())
        if (extra.size() > 1 && extra[0] == '-')
            return usageError("unknown option '" + extra + "'; see prism-shaderc --help");
    if (!app.remaining().empty()) o.inputs.insert(o.inputs.end(), app.remaining().begin(), app.remaining().end());
    if (o.inputs.empty() && o.programs.empty())
        return usageError(
            "no shader inputs: give shader files or directories, or --program NAME=FILE,... (see --help)");
    for (const auto& d : defines) {
        auto nv = splitDefine(d);
        if (!isIdentifier(nv.first))
            return usageError("-D " + d + ": '" + nv.first + "' is not a macro name; use -D NAME or -D NAME=VALUE");
        o.defines.push_back(nv);
    }
    if (auto error = parseTargetList(targets, o.targets); !error.empty())
        return usageError("--target " + targets + ": " + error);
    if (auto error = vulkanClientTargets(o, app.count("--target") > 0, targets); !error.empty())
        return usageError(error);
    o.errorFormat = errfmt == "msvc" ? ErrorFormat::Msvc : ErrorFormat::Gcc;
    o.warnUndocumentedLibraryModules = warnUndocumented == "all";
    if (o.jobs == 0) o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (o.glslVersion >= 150 && o.glslVersion < 300) o.glslProfile = "core";
    if (o.glslVersion < 150) o.glslProfile.clear();
    if (auto conflict = conflictOf(o, app); !conflict.empty()) return usageError(conflict);
    if (o.nameSpace.empty() && !o.output.empty()) o.nameSpace = defaultNamespace(o.output);
    if (o.client == "vulkan") {
        const auto env = parseSpirvEnv(o.targetEnv.empty() ? "vulkan1.2" : o.targetEnv);
        if (!env || o.targetEnv.starts_with("opengl"))
            return usageError("--target-env " + o.targetEnv +
                              ": not a Vulkan version; use vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3");
        o.rules = vulkanClientRules(*env);
    }
    if (o.baseDir.empty()) o.baseDir = std::filesystem::current_path().string();
    o.baseDir = std::filesystem::absolute(o.baseDir).lexically_normal().string();
    return {std::move(o), 0};
}

}  // namespace prism::shaderc
