// glslang's SPIR-V generator and SPIRV-Tools' validator behind one target-environment enum.
#include "spirv_codegen.hpp"

#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>

#include <array>
#include <map>
#include <memory>

namespace prism::shaderc {
namespace {

struct EnvRow {
    SpirvEnv env;
    std::string_view name;
    glslang::EShClient client;
    glslang::EShTargetClientVersion clientVersion;
    glslang::EShTargetLanguageVersion spirvVersion;
    spv_target_env tools;
};

// Each Vulkan version with the newest SPIR-V it guarantees (Vulkan spec, "Versions").
constexpr std::array<EnvRow, 5> kEnvs{{
    {SpirvEnv::Vulkan1_0, "vulkan1.0", glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0,
     glslang::EShTargetSpv_1_0, SPV_ENV_VULKAN_1_0},
    {SpirvEnv::Vulkan1_1, "vulkan1.1", glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1,
     glslang::EShTargetSpv_1_3, SPV_ENV_VULKAN_1_1},
    {SpirvEnv::Vulkan1_2, "vulkan1.2", glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2,
     glslang::EShTargetSpv_1_5, SPV_ENV_VULKAN_1_2},
    {SpirvEnv::Vulkan1_3, "vulkan1.3", glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3,
     glslang::EShTargetSpv_1_6, SPV_ENV_VULKAN_1_3},
    {SpirvEnv::OpenGL4_5, "opengl4.5", glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450,
     glslang::EShTargetSpv_1_0, SPV_ENV_OPENGL_4_5},
}};

const EnvRow& rowOf(SpirvEnv env) {
    return kEnvs[static_cast<std::size_t>(env)];
}

}  // namespace

std::optional<SpirvEnv> parseSpirvEnv(std::string_view name) {
    for (const auto& row : kEnvs)
        if (row.name == name) return row.env;
    return std::nullopt;
}

std::string_view spirvEnvName(SpirvEnv env) {
    return rowOf(env).name;
}

std::string spirvEnvNames() {
    std::string out;
    for (const auto& row : kEnvs) out += (out.empty() ? "" : ", ") + std::string(row.name);
    return out;
}

void configureShader(glslang::TShader& shader, EShLanguage stage, SpirvEnv env) {
    const auto& row = rowOf(env);
    shader.setEnvInput(glslang::EShSourceGlsl, stage, row.client, 100);
    shader.setEnvClient(row.client, row.clientVersion);
    shader.setEnvTarget(glslang::EShTargetSpv, row.spirvVersion);
}

EShMessages spirvMessages(SpirvEnv env) {
    const int rules =
        rowOf(env).client == glslang::EShClientVulkan ? EShMsgSpvRules | EShMsgVulkanRules : EShMsgSpvRules;
    return static_cast<EShMessages>(rules);
}

bool generateSpirv(const glslang::TProgram& program, EShLanguage stage, std::vector<std::uint32_t>& words,
                   std::string& log) {
    words.clear();
    const auto* intermediate = const_cast<glslang::TProgram&>(program).getIntermediate(stage);
    if (intermediate == nullptr) {
        log = "the program has no such stage";
        return false;
    }
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;  // unoptimised, no debug information: what glslc -O0 -g0 writes
    std::vector<unsigned int> out;
    glslang::GlslangToSpv(*intermediate, out, &logger, &options);
    log = logger.getAllMessages();
    words.assign(out.begin(), out.end());
    return !words.empty();
}

namespace {

// One SPIRV-Tools context per environment and thread: building one (its grammar tables)
// cost more than validating a stage. Validation itself is thread-safe only per context.
spvtools::SpirvTools& toolsFor(SpirvEnv env) {
    thread_local std::map<SpirvEnv, std::unique_ptr<spvtools::SpirvTools>> tools;
    auto& slot = tools[env];
    if (!slot) slot = std::make_unique<spvtools::SpirvTools>(rowOf(env).tools);
    return *slot;
}

}  // namespace

std::vector<Diagnostic> validateSpirv(std::span<const std::uint32_t> words, SpirvEnv env, const std::string& file,
                                      const std::string& what) {
    std::vector<Diagnostic> out;
    auto& tools = toolsFor(env);
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        out.push_back(makeError(
            file, 0, 0,
            "SPIRV-Tools rejected the SPIR-V of " + what + " for " + std::string(spirvEnvName(env)) + ": " + message));
    });
    const bool valid = tools.Validate(words.data(), words.size());
    tools.SetMessageConsumer(nullptr);  // it refers to `out`, which ends here
    if (!valid && out.empty()) out.push_back(makeError(file, 0, 0, "SPIRV-Tools rejected the SPIR-V of " + what));
    return out;
}

}  // namespace prism::shaderc
