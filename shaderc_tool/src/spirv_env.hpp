// Part of stage 1: the SPIR-V environments prism-shaderc knows, by glslc's --target-env
// spelling, and glslang's settings for each. The command line makes one (target_rules.hpp
// carries it to every later stage); spirv_codegen.hpp maps it to SPIRV-Tools' too.
//
//   if (auto env = parseSpirvEnv("vulkan1.2")) rules = vulkanClientRules(*env);
//   std::cerr << "takes " << spirvEnvNames();  // "vulkan1.0, vulkan1.1, ..."
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <glslang/Public/ShaderLang.h>

namespace prism::shaderc {

enum class SpirvEnv : std::uint8_t { Vulkan1_0, Vulkan1_1, Vulkan1_2, Vulkan1_3, OpenGL4_5 };

// "vulkan1.0" ... "vulkan1.3", "opengl4.5" (glslc's --target-env spellings).
std::optional<SpirvEnv> parseSpirvEnv(std::string_view name);
std::string_view spirvEnvName(SpirvEnv env);
// The names parseSpirvEnv takes, for an error message: "vulkan1.0, vulkan1.1, ...".
std::string spirvEnvNames();

// Sets `shader`'s input, client and SPIR-V target for `env` (as glslangValidator -V / -G
// and glslc --target-env do), before parse().
void configureShader(glslang::TShader& shader, EShLanguage stage, SpirvEnv env);
// The messages that parse() and link() take for `env`: SPIR-V rules, plus Vulkan rules for Vulkan.
EShMessages spirvMessages(SpirvEnv env);

}  // namespace prism::shaderc
