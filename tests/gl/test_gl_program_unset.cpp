// Uniforms nobody set (Program::unsetUniforms, reportUnsetUniforms) and typed handles
// (prism/catalog/uniform_handle.hpp) on a toon-like program of this test's own.
#include <glm/glm.hpp>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"

namespace {

using prism::catalog::GlslType;
using prism::catalog::UniformHandle;
using prism::gl::Program;

// What a generated header declares for the shader below (and one uniform it compiled out).
namespace toon {
struct Shader {};
inline constexpr UniformHandle<GlslType::Float, 1, Shader> u_bands{"u_bands"};
inline constexpr UniformHandle<GlslType::Vec3, 1, Shader> u_base{"u_base"};
inline constexpr UniformHandle<GlslType::Float, 1, Shader> u_rimPower{"u_rimPower"};  // not in this variant
}  // namespace toon

Program toonProgram() {
    prism::gl::ProgramSources sources;
    sources.label = "toon";
    sources.stages.push_back({prism::catalog::Stage::Vertex,
                              "#version 330 core\nin vec2 a_position;\n"
                              "void main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n",
                              {{0, "toon.vert"}}});
    sources.stages.push_back({prism::catalog::Stage::Fragment,
                              "#version 330 core\nuniform float u_bands;\nuniform vec3 u_base;\n"
                              "uniform sampler2D u_ramp;\nuniform  float u_gamma [2] = float[2](1.0, 2.2);\n"
                              "out vec4 c;\nvoid main() {\n"
                              "    float l = floor(0.7 * u_bands) / max(u_bands, 1.0);\n"
                              "    c = vec4(u_base * l * u_gamma[1], texture(u_ramp, vec2(l)).r);\n}\n",
                              {{0, "toon.frag"}}});
    sources.attributes.push_back({"a_position", 0});
    Program program(std::move(sources));
    program.setUnsetUniformCheck(true);
    return program;
}

class ProgramUnset : public prism::test::GlTest {};

TEST_F(ProgramUnset, NeverSetFloatIsReportedOnceByName) {
    Program program = toonProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set(toon::u_base, glm::vec3(1.0f));
    // The sampler stays at unit 0 and u_gamma has an initialiser: neither is reported.
    EXPECT_EQ(program.unsetUniforms(), std::vector<std::string>{"u_bands"});
    for (int i = 0; i < 3; ++i) program.reportUnsetUniforms();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'u_bands' is active but was never set"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("program 'toon'"), std::string::npos) << warnings[0];
}

TEST_F(ProgramUnset, ReloadedProgramIsCheckedAgain) {
    std::vector<std::string> warnings;
    for (int reload = 0; reload < 2; ++reload) {
        Program program = toonProgram();
        program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
        program.reportUnsetUniforms();
    }
    EXPECT_EQ(warnings.size(), 4u);  // u_bands and u_base, once per link
}

TEST_F(ProgramUnset, TypedSetMarksTheUniformSetAndDraws) {
    Program program = toonProgram();
    program.set(toon::u_bands, 4.0f);
    program.set(toon::u_base, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_TRUE(program.unsetUniforms().empty());
    prism::gl::Framebuffer fb(prism::test::kSize, prism::test::kSize);
    prism::test::drawTriangle(fb, program);
    // floor(0.7 * 4) / 4 = 0.5, times u_gamma[1] = 2.2: red saturates; an unset u_bands gives 0.
    EXPECT_EQ(fb.readImage8().at(prism::test::kSize / 2, prism::test::kSize / 2)[0], 255);
}

TEST_F(ProgramUnset, HandleOfACompiledOutUniformIsANoOpThatIsListed) {
    Program program = toonProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set(toon::u_rimPower, 2.0f);
    program.set(toon::u_rimPower, 3.0f);
    EXPECT_EQ(program.compiledOutUniforms(), std::vector<std::string>{"u_rimPower"});
    EXPECT_TRUE(program.unknownUniformReports().empty());
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ProgramUnset, OffByDefaultSwitchSilencesTheReport) {
    Program program = toonProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.setUnsetUniformCheck(false);
    program.reportUnsetUniforms();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(program.unsetUniforms().size(), 2u);  // the list is there either way
}

TEST_F(ProgramUnset, IntLiteralIntoAFloatIsSetNotDropped) {
    Program program = toonProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set("u_bands", 4);  // an int literal: exact as a float
    GLfloat bands = 0.0f;
    glGetUniformfv(program.id(), program.uniformLocation("u_bands"), &bands);
    EXPECT_EQ(bands, 4.0f);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(program.unsetUniforms(), std::vector<std::string>{"u_base"});
    program.set("u_bands", (1 << 24) + 1);  // no float holds it: reported, not rounded
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("is float but set() got a int"), std::string::npos) << warnings[0];
}

TEST_F(ProgramUnset, UnknownNameSaysDidYouMean) {
    Program program = toonProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set("u_band", 4.0f);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("(did you mean 'u_bands'?)"), std::string::npos) << warnings[0];
}

}  // namespace
