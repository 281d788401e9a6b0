// Unit tests of spirv_codegen.hpp: SPIR-V generated from a linked glslang program for a
// Vulkan environment, and SPIRV-Tools' verdict on good and broken words.
#include <gtest/gtest.h>

#include <glslang/Public/ResourceLimits.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "spirv_codegen.hpp"
#include "spirv_source_lines.hpp"
#include "validation_fixture.hpp"

namespace prism::shaderc {
namespace {

const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new test::GlslangEnvironment);

const char* const kVertex = R"(#version 450
layout(push_constant) uniform Push { mat4 mvp; } pc;
layout(set = 1, binding = 2) uniform Extra { vec4 tint; } extra;
layout(location = 0) in vec3 a_position;
layout(location = 0) out vec4 v_color;
void main() {
    v_color = extra.tint * float(gl_VertexIndex);
    gl_Position = pc.mvp * vec4(a_position, 1.0);
}
)";

// Parses and links `text` as one stage for `env`; null when either step fails.
std::unique_ptr<glslang::TProgram> linkedProgram(glslang::TShader& shader, const char* text, SpirvEnv env) {
    shader.setStrings(&text, 1);
    configureShader(shader, EShLangVertex, env);
    if (!shader.parse(GetDefaultResources(), 100, ENoProfile, false, false, spirvMessages(env))) return nullptr;
    auto program = std::make_unique<glslang::TProgram>();
    program->addShader(&shader);
    if (!program->link(spirvMessages(env))) return nullptr;
    return program;
}

TEST(SpirvCodegen, TargetEnvironmentsByGlslcName) {
    EXPECT_EQ(parseSpirvEnv("vulkan1.0"), SpirvEnv::Vulkan1_0);
    EXPECT_EQ(parseSpirvEnv("vulkan1.3"), SpirvEnv::Vulkan1_3);
    EXPECT_EQ(parseSpirvEnv("opengl4.5"), SpirvEnv::OpenGL4_5);
    EXPECT_FALSE(parseSpirvEnv("vulkan1.4").has_value());
    EXPECT_FALSE(parseSpirvEnv("Vulkan1.2").has_value());
    for (auto env : {SpirvEnv::Vulkan1_0, SpirvEnv::Vulkan1_1, SpirvEnv::Vulkan1_2, SpirvEnv::Vulkan1_3})
        EXPECT_EQ(parseSpirvEnv(spirvEnvName(env)), env);
    EXPECT_EQ(spirvEnvNames(), "vulkan1.0, vulkan1.1, vulkan1.2, vulkan1.3, opengl4.5");
}

// The words of kVertex for `env`; empty (with a test failure) when a step fails.
std::vector<std::uint32_t> vertexWords(SpirvEnv env) {
    glslang::TShader shader(EShLangVertex);
    auto program = linkedProgram(shader, kVertex, env);
    EXPECT_TRUE(program) << shader.getInfoLog();
    std::vector<std::uint32_t> words;
    std::string log;
    if (program) {
        EXPECT_TRUE(generateSpirv(*program, EShLangVertex, words, log)) << log;
    }
    return words;
}

TEST(SpirvCodegen, VulkanStageBecomesValidSpirv) {
    const auto words = vertexWords(SpirvEnv::Vulkan1_2);
    ASSERT_GT(words.size(), 5u);
    EXPECT_EQ(words[0], 0x07230203u);  // the SPIR-V magic number
    EXPECT_EQ(words[1], 0x00010500u);  // Vulkan 1.2 → SPIR-V 1.5
    EXPECT_TRUE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a, vert stage").empty());
}

TEST(SpirvCodegen, VersionFollowsTheEnvironment) {
    const auto words = vertexWords(SpirvEnv::Vulkan1_0);
    ASSERT_GT(words.size(), 5u);
    EXPECT_EQ(words[1], 0x00010000u);
    EXPECT_EQ(vertexWords(SpirvEnv::Vulkan1_3).at(1), 0x00010600u);
}

TEST(SpirvCodegen, NoStageNoWords) {
    glslang::TShader shader(EShLangVertex);
    auto program = linkedProgram(shader, kVertex, SpirvEnv::Vulkan1_2);
    ASSERT_TRUE(program);
    std::vector<std::uint32_t> words{1, 2};
    std::string log;
    EXPECT_FALSE(generateSpirv(*program, EShLangFragment, words, log));
    EXPECT_TRUE(words.empty());
    EXPECT_NE(log.find("no such stage"), std::string::npos);
}

TEST(SpirvCodegen, PushConstantsAreRefusedOutsideVulkan) {
    glslang::TShader shader(EShLangVertex);
    EXPECT_FALSE(linkedProgram(shader, kVertex, SpirvEnv::OpenGL4_5));
    EXPECT_NE(std::string(shader.getInfoLog()).find("push_constant"), std::string::npos) << shader.getInfoLog();
}

TEST(SpirvCodegen, BrokenWordsAreAnErrorNamingTheStage) {
    glslang::TShader shader(EShLangVertex);
    auto program = linkedProgram(shader, kVertex, SpirvEnv::Vulkan1_2);
    ASSERT_TRUE(program);
    std::vector<std::uint32_t> words;
    std::string log;
    ASSERT_TRUE(generateSpirv(*program, EShLangVertex, words, log));
    words[3] = 2;  // the id bound below the ids in use
    const auto errors = validateSpirv(words, SpirvEnv::Vulkan1_2, "shaders/a.vert", "program a, vert stage");
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].file, "shaders/a.vert");
    EXPECT_NE(errors[0].message.find("program a, vert stage"), std::string::npos) << errors[0].message;
    EXPECT_NE(errors[0].message.find("vulkan1.2"), std::string::npos) << errors[0].message;
    // Vulkan 1.0 takes SPIR-V 1.0 only: 1.5 words are refused.
    ASSERT_TRUE(generateSpirv(*program, EShLangVertex, words, log));
    EXPECT_FALSE(validateSpirv(words, SpirvEnv::Vulkan1_0, "a.vert", "program a").empty());
}

// The validator's verdict is remembered per process for accepted words only: the same
// words in another environment are judged again, and a rejected module says so every time,
// naming the stage that asked.
TEST(SpirvCodegen, AnAcceptedModuleIsRememberedByItsWordsAndEnvironmentOnly) {
    auto words = vertexWords(SpirvEnv::Vulkan1_2);
    ASSERT_GT(words.size(), 5u);
    EXPECT_TRUE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a").empty());
    EXPECT_TRUE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a").empty());
    EXPECT_FALSE(validateSpirv(words, SpirvEnv::Vulkan1_0, "a.vert", "program a").empty());
    words[3] = 2;  // the id bound below the ids in use
    EXPECT_FALSE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a").empty());
    const auto again = validateSpirv(words, SpirvEnv::Vulkan1_2, "b.vert", "program b");
    ASSERT_FALSE(again.empty());
    EXPECT_EQ(again[0].file, "b.vert");
    EXPECT_NE(again[0].message.find("program b"), std::string::npos) << again[0].message;
}

const char* const kScalarVertex = R"(#version 450
#extension GL_EXT_scalar_block_layout : require
layout(scalar, set = 0, binding = 0) buffer Data { vec2 a; vec3 b; float c; } data;
void main() { gl_Position = vec4(data.b, data.a.x + data.c); }
)";

// GL_EXT_scalar_block_layout in the source selects spirv-val's --scalar-block-layout: the
// same words without it (its OpSourceExtension renamed) break relaxed block layout, and
// the rejection names the block the validator's instruction declares, for the locator.
TEST(SpirvCodegen, TheModulesOwnExtensionsSelectItsBlockLayoutRules) {
    glslang::TShader shader(EShLangVertex);
    auto program = linkedProgram(shader, kScalarVertex, SpirvEnv::Vulkan1_2);
    ASSERT_TRUE(program) << shader.getInfoLog();
    std::vector<std::uint32_t> words;
    std::string log;
    ASSERT_TRUE(generateSpirv(*program, EShLangVertex, words, log)) << log;
    EXPECT_TRUE(blockLayoutRulesOf(words).scalar);
    EXPECT_FALSE(blockLayoutRulesOf(words).workgroupScalar);
    EXPECT_FALSE(blockLayoutRulesOf(vertexWords(SpirvEnv::Vulkan1_2)).scalar);
    EXPECT_TRUE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a").empty());

    for (std::size_t at = 5; at < words.size(); at += words[at] >> 16)
        if ((words[at] & 0xFFFF) == 4) words[at + 1] ^= 'G' ^ 'X';  // OpSourceExtension "XL_EXT_..."
    EXPECT_FALSE(blockLayoutRulesOf(words).scalar);
    std::vector<std::string> named;
    const SpirvSiteLocator locate = [&](const SpirvSite& site, Diagnostic& d) {
        named = site.names;
        d.line = 3;
        return true;
    };
    const auto errors = validateSpirv(words, SpirvEnv::Vulkan1_2, "a.vert", "program a", locate);
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors[0].message.find("layout"), std::string::npos) << errors[0].message;
    EXPECT_EQ(errors[0].line, 3);
    EXPECT_NE(std::find(named.begin(), named.end(), "Data"), named.end()) << ::testing::PrintToString(named);
}

// A flattened stage's `#line N S` leaves glslang's OpLines without S; the words made for
// locating a message name each OpLine's file by its source number, and a message about a
// statement (here an OpStore made invalid) is at that statement's source and line.
TEST(SpirvCodegen, LineInfoNamesTheSourceNumberOfAStatement) {
    const char* const text =
        "#version 450\n#line 1 0\nlayout(location = 0) out vec4 o;\n#line 7 2\n"
        "void main() {\n    o = vec4(1.0);\n}\n";
    glslang::TShader shader(EShLangFragment);
    shader.setStrings(&text, 1);
    configureShader(shader, EShLangFragment, SpirvEnv::Vulkan1_2);
    ASSERT_TRUE(shader.parse(GetDefaultResources(), 100, ENoProfile, false, false, spirvMessages(SpirvEnv::Vulkan1_2)))
        << shader.getInfoLog();
    glslang::TProgram program;
    program.addShader(&shader);
    ASSERT_TRUE(program.link(spirvMessages(SpirvEnv::Vulkan1_2))) << program.getInfoLog();
    std::vector<std::uint32_t> plain, words;
    std::string log;
    ASSERT_TRUE(generateSpirv(program, EShLangFragment, plain, log)) << log;
    ASSERT_TRUE(generateSpirvWithSourceNumbers(program, EShLangFragment, words, log)) << log;
    std::vector<std::uint32_t> again;
    ASSERT_TRUE(generateSpirv(program, EShLangFragment, again, log)) << log;
    EXPECT_EQ(again, plain) << "the stage's tree is restored: its plain words do not change";
    for (std::size_t at = 5; at < words.size(); at += words[at] >> 16)
        if ((words[at] & 0xFFFF) == 62) words[at + 2] = words[at + 1];  // OpStore o, o: the types differ
    SpirvSite seen;
    const SpirvSiteLocator locate = [&](const SpirvSite& site, Diagnostic&) {
        seen = site;
        return true;
    };
    EXPECT_FALSE(validateSpirv(words, SpirvEnv::Vulkan1_2, "a.frag", "program a", locate).empty());
    EXPECT_TRUE(seen.inFunction);
    EXPECT_EQ(seen.lineFile, "2");
    EXPECT_EQ(seen.line, 8);
}

}  // namespace
}  // namespace prism::shaderc
