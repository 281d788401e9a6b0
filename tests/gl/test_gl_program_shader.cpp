// A Program built from a catalogue variant knows its shader at run time (Program::builtFrom),
// so set() with another shader's typed handle is reported once per handle and skipped;
// ProgramOf<Shader> makes the same mistake a compile error (typed_uniforms/other_shader_handle.cpp).
#include <glm/glm.hpp>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/shaders.hpp"

namespace {

namespace shaders = prism::shaders;
using prism::gl::Program;

const prism::catalog::Variant& defaultVariant(shaders::ShaderId id) {
    const auto* variant = prism::catalog::findVariant(shaders::shaderInfo(id), {});
    EXPECT_NE(variant, nullptr);
    return *variant;
}

glm::vec4 colorOf(const Program& program) {
    glm::vec4 value(-1.0f);
    glGetUniformfv(program.id(), program.uniformLocation("u_color"), &value.x);
    return value;
}

class ProgramShader : public prism::test::GlTest {};

TEST_F(ProgramShader, KnowsTheShaderOfItsVariant) {
    Program phong(defaultVariant(shaders::ShaderId::phong), shaders::kCatalog.contractAttributes, "phong");
    EXPECT_TRUE(phong.builtFrom(shaders::shaderInfo(shaders::ShaderId::phong)));
    EXPECT_FALSE(phong.builtFrom(shaders::shaderInfo(shaders::ShaderId::unicolor)));
    EXPECT_FALSE(phong.builtFrom(shaders::shaderInfo(shaders::ShaderId::flat)));
}

// unicolor::u_color has phong's name and type: only the shader tells them apart.
TEST_F(ProgramShader, AnotherShadersHandleIsReportedOnceAndSkipped) {
    Program phong(defaultVariant(shaders::ShaderId::phong), shaders::kCatalog.contractAttributes, "phong");
    std::vector<std::string> warnings;
    phong.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    for (int i = 0; i < 3; ++i) phong.set(shaders::unicolor::u_color, glm::vec4(1.0f));
    EXPECT_EQ(colorOf(phong), glm::vec4(0.0f)) << "the foreign handle's value must not be set";
    EXPECT_EQ(phong.foreignHandleReports(), std::vector<std::string>{"unicolor::u_color"});
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("program 'phong': set() of handle unicolor::u_color, which belongs to shader "
                               "'unicolor', on a program of another shader"),
              std::string::npos)
        << warnings[0];

    phong.set(shaders::phong::u_color, glm::vec4(0.5f));      // its own handle: set
    phong.set(shaders::contract::u_color, glm::vec4(0.25f));  // the contract's handles fit every shader
    EXPECT_EQ(colorOf(phong), glm::vec4(0.25f));
    EXPECT_EQ(warnings.size(), 1u);
}

// Composed and raw programs know no shader: every shader's handle is taken by its name.
TEST_F(ProgramShader, ProgramWithoutAVariantTakesAnyShadersHandle) {
    auto sources = prism::gl::sourcesFromVariant(defaultVariant(shaders::ShaderId::phong),
                                                 shaders::kCatalog.contractAttributes, "raw phong");
    sources.variant = nullptr;
    Program raw(std::move(sources));
    raw.set(shaders::unicolor::u_color, glm::vec4(1.0f));
    EXPECT_FALSE(raw.builtFrom(shaders::shaderInfo(shaders::ShaderId::phong)));
    EXPECT_TRUE(raw.foreignHandleReports().empty());
    EXPECT_EQ(colorOf(raw), glm::vec4(1.0f));
}

}  // namespace
