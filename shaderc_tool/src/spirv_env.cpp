// The SPIR-V environments' names (spirv_env.hpp).
#include "spirv_env.hpp"

#include <array>

namespace prism::shaderc {
namespace {

// In SpirvEnv's order.
constexpr std::array<std::string_view, 5> kEnvNames{"vulkan1.0", "vulkan1.1", "vulkan1.2", "vulkan1.3", "opengl4.5"};

struct GlslangEnv {
    glslang::EShClient client;
    glslang::EShTargetClientVersion clientVersion;
    glslang::EShTargetLanguageVersion spirvVersion;
};

// Each Vulkan version with the newest SPIR-V it guarantees (Vulkan spec, "Versions").
constexpr std::array<GlslangEnv, 5> kGlslangEnvs{{
    {glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0, glslang::EShTargetSpv_1_0},
    {glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1, glslang::EShTargetSpv_1_3},
    {glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2, glslang::EShTargetSpv_1_5},
    {glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3, glslang::EShTargetSpv_1_6},
    {glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450, glslang::EShTargetSpv_1_0},
}};

const GlslangEnv& glslangEnvOf(SpirvEnv env) {
    return kGlslangEnvs[static_cast<std::size_t>(env)];
}

}  // namespace

std::optional<SpirvEnv> parseSpirvEnv(std::string_view name) {
    for (std::size_t i = 0; i < kEnvNames.size(); ++i)
        if (kEnvNames[i] == name) return static_cast<SpirvEnv>(i);
    return std::nullopt;
}

std::string_view spirvEnvName(SpirvEnv env) {
    return kEnvNames[static_cast<std::size_t>(env)];
}

std::string spirvEnvNames() {
    std::string out;
    for (const auto name : kEnvNames) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

void configureShader(glslang::TShader& shader, EShLanguage stage, SpirvEnv env) {
    const auto& row = glslangEnvOf(env);
    shader.setEnvInput(glslang::EShSourceGlsl, stage, row.client, 100);
    shader.setEnvClient(row.client, row.clientVersion);
    shader.setEnvTarget(glslang::EShTargetSpv, row.spirvVersion);
}

EShMessages spirvMessages(SpirvEnv env) {
    const int rules =
        glslangEnvOf(env).client == glslang::EShClientVulkan ? EShMsgSpvRules | EShMsgVulkanRules : EShMsgSpvRules;
    return static_cast<EShMessages>(rules);
}

}  // namespace prism::shaderc
