// The classification of prism-shaderc's options (see output_options.hpp).
#include "output_options.hpp"

#include <array>
#include <filesystem>

#include "program_argument.hpp"
#include "shown_path.hpp"

namespace prism::shaderc {
namespace {

using Lines = std::vector<std::string>;
constexpr auto kChanges = OptionEffect::ChangesOutputs;
constexpr auto kNoChange = OptionEffect::NoOutputChange;

// A path as embedded. Asked before the inputs are checked, so an empty one (--program p=a,,b)
// stays empty for the error that follows.
std::string shown(const std::string& path, const Options& o) {
    return path.empty() ? path : recordedName(path, o);
}

void addIfGiven(Lines& out, const char* tag, const std::string& value) {
    if (!value.empty()) out.push_back(std::string(tag) + " " + value);
}

// The rows the data file's sources record prints, in its order (the golden files hold it).
constexpr std::array kRules{
    OptionRule{"--namespace", kChanges, kDataFileRecord,
               [](const Options& o, Lines& out) { out.push_back("ns " + o.nameSpace); }},
    OptionRule{"--glsl-version", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   out.push_back("glsl " + std::to_string(o.glslVersion) + " " + o.glslProfile);
               }},
    OptionRule{"--client", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   if (o.rules.spirvEnv) out.push_back("client vulkan " + std::string(spirvEnvName(*o.rules.spirvEnv)));
               }},
    OptionRule{"--target-env", kChanges, kDataFileRecord | kValidationPack,
               [](const Options&, Lines&) {}},  // in --client's line
    OptionRule{"-o", kChanges, kDataFileRecord,
               [](const Options& o, Lines& out) {
                   out.push_back("out " + std::filesystem::path(o.output).filename().string());
               }},
    OptionRule{"-D", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   for (const auto& [name, value] : o.defines) out.push_back("-D " + name + "=" + value);
               }},
    OptionRule{"--variant", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   for (const auto& filter : o.variantFilters) out.push_back("--variant " + filter);
               }},
    OptionRule{"--target", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   if (o.targets != std::vector<Target>{Target::Gl})
                       out.push_back("--target " + targetListText(o.targets));
               }},
    OptionRule{"--contract", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   for (const auto& c : o.contracts) out.push_back("--contract " + shown(c, o));
               }},
    OptionRule{"-I", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   for (const auto& dir : o.includeDirs) out.push_back("-I " + shown(dir, o));
               }},
    OptionRule{"inputs", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   for (const auto& input : o.inputs) out.push_back("in " + shown(input, o));
               }},
    OptionRule{"--program", kChanges, kDataFileRecord | kValidationPack,
               [](const Options& o, Lines& out) {
                   const auto embedded = [&](const std::string& path) { return shown(path, o); };
                   for (const auto& d : o.programs) out.push_back("--program " + declarationWithPaths(d, embedded));
               }},
    // The rows only the one record hashes: which files the run writes, where paths point.
    OptionRule{"--emit-glsl", kChanges, kNoOtherKey,
               [](const Options& o, Lines& out) { addIfGiven(out, "--emit-glsl", o.emitGlslDir); }},
    OptionRule{"--emit-spirv", kChanges, kNoOtherKey,
               [](const Options& o, Lines& out) { addIfGiven(out, "--emit-spirv", o.emitSpirvDir); }},
    OptionRule{"--emit-web", kChanges, kNoOtherKey,
               [](const Options& o, Lines& out) { addIfGiven(out, "--emit-web", o.emitWeb); }},
    OptionRule{"--emit-reflection", kChanges, kNoOtherKey,
               [](const Options& o, Lines& out) { addIfGiven(out, "--emit-reflection", o.emitReflection); }},
    OptionRule{"--check", kChanges, kNoOtherKey,
               [](const Options& o, Lines& out) {
                   if (o.checkOnly) out.push_back("--check");
               }},
    OptionRule{"--base-dir", kChanges, kValidationPack,
               [](const Options& o, Lines& out) { out.push_back("--base-dir " + o.baseDir); }},
    OptionRule{"--warn-undocumented-modules", kChanges, kValidationPack,
               [](const Options& o, Lines& out) {
                   if (o.warnUndocumentedLibraryModules) out.push_back("--warn-undocumented-modules all");
               }},
    // Rows that change how the run goes, never what it writes.
    OptionRule{"--depfile", kNoChange, kNoOtherKey, nullptr},  // rewritten by every run, the no-op too
    OptionRule{"--stamp", kNoChange, kNoOtherKey, nullptr},    // touched by every run, the no-op too
    OptionRule{"--cache-dir", kNoChange, kNoOtherKey, nullptr},
    OptionRule{"--errfmt", kNoChange, kNoOtherKey, nullptr},  // how diagnostics print; a no-op prints none
    OptionRule{"-j", kNoChange, kNoOtherKey, nullptr},
    OptionRule{"--stats", kNoChange, kNoOtherKey, nullptr},
    OptionRule{"--revalidate", kNoChange, kNoOtherKey, nullptr},          // never asks the record
    OptionRule{"--no-variant-sharing", kNoChange, kNoOtherKey, nullptr},  // the same outputs by another route
    OptionRule{"--help", kNoChange, kNoOtherKey, nullptr},
    OptionRule{"--version", kNoChange, kNoOtherKey, nullptr},
};

}  // namespace

std::span<const OptionRule> optionRules() {
    return kRules;
}

const OptionRule* optionRule(std::string_view name) {
    for (const auto& rule : kRules)
        if (rule.name == name) return &rule;
    return nullptr;
}

std::vector<std::string> outputOptionLines(const Options& o) {
    std::vector<std::string> lines;
    for (const auto& rule : kRules)
        if (rule.effect == OptionEffect::ChangesOutputs) rule.lines(o, lines);
    return lines;
}

std::vector<std::string> outputOptionLines(const Options& o, OptionKey key) {
    std::vector<std::string> lines;
    for (const auto& rule : kRules)
        if (rule.effect == OptionEffect::ChangesOutputs && (rule.keys & key) != 0) rule.lines(o, lines);
    return lines;
}

std::string validationCacheDir(const Options& o) {
    if (o.cacheDir == "none") return {};
    if (!o.cacheDir.empty()) return o.cacheDir;
    if (o.stamp.empty()) return {};
    const auto parent = std::filesystem::path(o.stamp).parent_path();
    return (parent.empty() ? std::filesystem::path("prism-shaderc-cache") : parent / "prism-shaderc-cache").string();
}

}  // namespace prism::shaderc
