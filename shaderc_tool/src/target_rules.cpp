// The client and target rules (see target_rules.hpp).
#include "target_rules.hpp"

namespace prism::shaderc {

EShMessages TargetRules::messages() const {
    return spirvEnv ? spirvMessages(*spirvEnv) : EShMsgDefault;
}

void TargetRules::configure(glslang::TShader& shader, EShLanguage stage) const {
    if (!spirvEnv) return;
    configureShader(shader, stage, *spirvEnv);
    if (!relaxedLayout) return;
    shader.setEnvInputVulkanRulesRelaxed();
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
}

TargetRules openGlClientRules() {
    return {};
}

TargetRules vulkanClientRules(SpirvEnv env) {
    const bool vulkan = env != SpirvEnv::OpenGL4_5;
    return {.spirvEnv = env,
            .relaxedLayout = false,
            .linksStageByStage = vulkan,
            .checksContract = false,
            .needsFragmentStage = false,
            .takesVulkanOnlyStages = true,
            .explainsVulkanGlsl = false};
}

TargetRules spirvTargetRules() {
    return {.spirvEnv = SpirvEnv::Vulkan1_1,
            .relaxedLayout = true,
            .linksStageByStage = false,
            .checksContract = false,
            .needsFragmentStage = true,
            .takesVulkanOnlyStages = false,
            .explainsVulkanGlsl = false};
}

}  // namespace prism::shaderc
