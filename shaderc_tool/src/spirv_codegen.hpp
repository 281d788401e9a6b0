// SPIR-V out of glslang, and SPIRV-Tools' check of it: the one place that knows how a
// target environment (Vulkan 1.0-1.3, OpenGL 4.5) maps to glslang's client and SPIR-V
// versions and to SPIRV-Tools' environment. Client-neutral: it takes glslang objects and a
// SpirvEnv, never catalogue types, so every SPIR-V producer (the Vulkan client, SPIR-V
// targets) shares it.
//
//   glslang::TShader shader(EShLangVertex);
//   configureShader(shader, EShLangVertex, SpirvEnv::Vulkan1_2);
//   shader.parse(GetDefaultResources(), 100, ENoProfile, false, false, spirvMessages(SpirvEnv::Vulkan1_2));
//   ... program.addShader(&shader); program.link(spirvMessages(SpirvEnv::Vulkan1_2));
//   std::vector<std::uint32_t> words;
//   std::string log;
//   if (!generateSpirv(program, EShLangVertex, words, log)) ...;
//   auto diagnostics = validateSpirv(words, SpirvEnv::Vulkan1_2, "shaders/blur.vert", "program blur, vert stage");
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diagnostics.hpp"
#include "spirv_env.hpp"

namespace prism::shaderc {

// configureShader() and spirvMessages(): spirv_env.hpp.

// The SPIR-V words of `stage` of a linked `program` (glslang's generator, unoptimised,
// no debug information, as glslc -O0 -g0 writes them; `withLineInfo`: with OpLine
// instructions, only to locate a validator message). False with glslang's log when it
// produced nothing.
bool generateSpirv(const glslang::TProgram& program, EShLanguage stage, std::vector<std::uint32_t>& words,
                   std::string& log, bool withLineInfo = false);

// The block layout rules a module relies on, as its source asked for them: glslang writes
// each `#extension` the source enables as an OpSourceExtension (also at -g0), and
// GL_EXT_scalar_block_layout selects spirv-val's --scalar-block-layout (with
// GL_EXT_shared_memory_block also --workgroup-scalar-block-layout). Relaxed block layout is
// SPIRV-Tools' own default for Vulkan 1.1 and newer (VK_KHR_relaxed_block_layout is core).
struct BlockLayoutRules {
    bool scalar = false;
    bool workgroupScalar = false;
    auto operator<=>(const BlockLayoutRules&) const = default;
};
BlockLayoutRules blockLayoutRulesOf(std::span<const std::uint32_t> words);

// Where a validator message points in the module: the OpName of the ids its instruction
// names (a struct's is its block's type name), in the order the instruction names them;
// whether it is in a function's body; and the OpLine before it (words with line info), its
// file as glslang named it.
struct SpirvSite {
    std::vector<std::string> names;
    bool inFunction = false;
    std::string lineFile;
    int line = 0;  // 0: no OpLine before it
};
// Maps a site to a file:line (with a column when known) in the stage's source; false when not found.
using SpirvSiteLocator = std::function<bool(const SpirvSite&, Diagnostic&)>;

// SPIRV-Tools' validator on `words` for `env`, with the module's own block layout rules:
// one error per message, at `file` (the stage's source), saying `what` failed (e.g.
// "program blur, vert stage"); `locate`, when given, moves it to the declaration the
// message's instruction names. Empty when valid.
std::vector<Diagnostic> validateSpirv(std::span<const std::uint32_t> words, SpirvEnv env, const std::string& file,
                                      const std::string& what, const SpirvSiteLocator& locate = {});

// What validateSpirv has run in this process: the modules SPIRV-Tools validated (a module
// it accepted before is not validated again) and their CPU time, summed over threads.
// --stats prints it, so the validator's share of a check is measured, not guessed.
struct SpirvValidatorUse {
    std::size_t modules = 0;
    double cpuMs = 0;
};
SpirvValidatorUse spirvValidatorUse();

}  // namespace prism::shaderc
