// The client and target rules, decided once: how a program is compiled, checked and linked
// (SPIR-V environment, layout rules, which stages it may have, how its stages link). Stage 1
// (args.cpp) makes the client's rules from --client and --target-env into Options::rules;
// the spirv target has its own (spirvTargetRules). The later stages read these fields and
// never ask which client it is.
//
//   const TargetRules rules = vulkanClientRules(SpirvEnv::Vulkan1_2);
//   rules.configure(shader, EShLangFragment);
//   shader.parse(..., rules.messages());
//   if (rules.linksStageByStage) ...;  // each stage a program of its own, as glslc compiles it
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <optional>

#include "spirv_env.hpp"

namespace prism::shaderc {

struct TargetRules {
    // Set: each stage is compiled to SPIR-V for it, validated by SPIRV-Tools and reflected
    // from the words (vulkan_reflection.hpp); empty: OpenGL driver GLSL, reflected by glslang.
    std::optional<SpirvEnv> spirvEnv;
    // The spirv target's relaxed Vulkan rules: GL-style source, its loose uniforms in one
    // std140 block per stage, locations and bindings assigned by glslang.
    bool relaxedLayout = false;
    // Each stage linked in a program of its own, as glslc compiles it (the API links no
    // blocks by name); the descriptors and ray-tracing data are checked across stages instead.
    bool linksStageByStage = false;
    // The binding contract is checked: the runtime feeds the program's uniforms by name.
    bool checksContract = true;
    // Every program has a fragment stage (a Vulkan pipeline may rasterise without one).
    bool needsFragmentStage = true;
    // Mesh, task and ray-tracing stages are taken (Vulkan GLSL).
    bool takesVulkanOnlyStages = false;
    // glslang's refusal of Vulkan GLSL is explained as such, naming --client vulkan.
    bool explainsVulkanGlsl = true;

    // The messages that glslang's parse() and link() take.
    EShMessages messages() const;
    // Sets `shader`'s client, SPIR-V target and rules, before parse(); nothing for driver GLSL.
    void configure(glslang::TShader& shader, EShLanguage stage) const;
    bool operator==(const TargetRules&) const = default;
};

// The OpenGL client's: driver GLSL, the binding contract, a fragment stage in every program.
TargetRules openGlClientRules();
// The Vulkan client's (--client vulkan --target-env ...): SPIR-V for `env`, stages linked one by one.
TargetRules vulkanClientRules(SpirvEnv env);
// The spirv target's (spirv_target.hpp): OpenGL sources as SPIR-V for Vulkan 1.1 under relaxed rules.
TargetRules spirvTargetRules();

}  // namespace prism::shaderc
