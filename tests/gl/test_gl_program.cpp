// Programs from a catalogue variant: rendering, driver errors mapped to module
// files, and uniforms that are checked and reported once.
#include <glm/glm.hpp>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"

namespace {

using namespace prism::test;
using prism::gl::Program;

class ProgramTest : public GlTest {
  protected:
    Program solidProgram() const {
        const auto* variant = prism::catalog::findVariant(kShaders[0], {});
        EXPECT_NE(variant, nullptr);
        return Program(*variant, kCatalog.contractAttributes, "solid");
    }
};

TEST_F(ProgramTest, VariantRendersTriangleInUniformColour) {
    Program program = solidProgram();
    program.set("u_color", glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
    const float weights[] = {0.25f, 0.5f, 0.25f};
    program.set("u_weights", std::span<const float>(weights));

    prism::gl::Framebuffer fb(kSize, kSize);
    drawTriangle(fb, program);
    const prism::image::Image8 img = fb.readImage8();
    EXPECT_EQ(img.at(kSize / 2, kSize / 2), (prism::image::Rgba8{255, 128, 64, 255}));
    EXPECT_EQ(img.at(1, 1), (prism::image::Rgba8{0, 0, 0, 255}));
    EXPECT_EQ(img.at(kSize - 2, kSize - 2), (prism::image::Rgba8{0, 0, 0, 255}));
    // The triangle's wide base is at the bottom of the image (row 0 = top).
    EXPECT_EQ(img.at(kSize * 3 / 10, kSize * 7 / 10), (prism::image::Rgba8{255, 128, 64, 255}));
    EXPECT_EQ(img.at(kSize * 3 / 10, kSize * 3 / 10), (prism::image::Rgba8{0, 0, 0, 255}));
    EXPECT_TRUE(program.unknownUniformReports().empty());
    EXPECT_TRUE(program.typeMismatchReports().empty());
}

TEST_F(ProgramTest, ArrayElementsAreAddressableByIndex) {
    Program program = solidProgram();
    EXPECT_TRUE(program.hasUniform("u_weights"));
    EXPECT_TRUE(program.hasUniform("u_weights[2]"));
    EXPECT_FALSE(program.hasUniform("u_weights[3]"));
    program.set("u_color", glm::vec4(1.0f));
    const float zeros[] = {0.f, 0.f, 0.f};
    program.set("u_weights", std::span<const float>(zeros));
    program.set("u_weights[2]", 0.5f);  // only the last element

    prism::gl::Framebuffer fb(kSize, kSize);
    drawTriangle(fb, program);
    EXPECT_EQ(fb.readImage8().at(kSize / 2, kSize / 2), (prism::image::Rgba8{128, 128, 128, 128}));

    const float four[] = {1.f, 1.f, 1.f, 1.f};
    EXPECT_THROW(program.set("u_weights", std::span<const float>(four)), std::length_error);
    EXPECT_THROW(program.set("u_weights[1]", std::span<const float>(four, 3)), std::length_error);
}

TEST_F(ProgramTest, ContractAttributeLocationsAreBoundBeforeLink) {
    Program program = solidProgram();
    EXPECT_EQ(glGetAttribLocation(program.id(), "a_position"), 0);
}

TEST_F(ProgramTest, CompileErrorIsMappedToModuleFileAndLine) {
    const auto* broken = prism::catalog::findVariant(kShaders[0], {{"BROKEN", "1"}});
    ASSERT_NE(broken, nullptr);
    try {
        Program program(*broken, kCatalog.contractAttributes, "solid");
        FAIL() << "the broken variant linked";
    } catch (const prism::gl::ShaderBuildError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("fragment shader of program 'solid'"), std::string::npos) << what;
        EXPECT_NE(what.find("modules/colors.glsl:3:"), std::string::npos) << what;
        EXPECT_NE(what.find("undeclared_thing"), std::string::npos) << what;
        // The raw driver log still uses Mesa's numbering: source 1, line 3.
        EXPECT_NE(e.driverLog().find("1:3("), std::string::npos) << e.driverLog();
    }
}

TEST_F(ProgramTest, LinkErrorIsReported) {
    prism::gl::ProgramSources sources;
    sources.label = "unlinkable";
    sources.stages.push_back({prism::catalog::Stage::Vertex,
                              "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n",
                              {{0, "a.vert"}}});
    sources.stages.push_back({prism::catalog::Stage::Fragment,
                              "#version 330 core\nfloat declaredOnly();\nout vec4 c;\n"
                              "void main() { c = vec4(declaredOnly()); }\n",
                              {{0, "a.frag"}}});
    try {
        Program program(std::move(sources));
        FAIL() << "a call of a function without a body linked";
    } catch (const prism::gl::ShaderBuildError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("cannot link program 'unlinkable'"), std::string::npos) << what;
        EXPECT_NE(what.find("declaredOnly"), std::string::npos) << what;
    }
}

TEST_F(ProgramTest, UnknownUniformIsReportedExactlyOnce) {
    Program program = solidProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    for (int i = 0; i < 3; ++i) program.set("u_colour", glm::vec4(1.0f));  // misspelt
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'u_colour'"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("program 'solid'"), std::string::npos) << warnings[0];
    EXPECT_EQ(program.unknownUniformReports(), std::vector<std::string>{"u_colour"});
    // A second unknown name is reported too, once.
    program.set("u_other", 1.0f);
    program.set("u_other", 2.0f);
    EXPECT_EQ(warnings.size(), 2u);
    EXPECT_EQ(program.unknownUniformReports(), (std::vector<std::string>{"u_colour", "u_other"}));
}

TEST_F(ProgramTest, DefaultWarningGoesToStderrOnce) {
    Program program = solidProgram();
    ::testing::internal::CaptureStderr();
    for (int i = 0; i < 3; ++i) program.set("u_nope", 1);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("u_nope"), std::string::npos) << err;
    EXPECT_EQ(err.find("u_nope"), err.rfind("u_nope")) << "reported more than once:\n" << err;
}

TEST_F(ProgramTest, WrongTypeIsReportedOnceAndSkipped) {
    Program program = solidProgram();
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set("u_color", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    for (int i = 0; i < 3; ++i) program.set("u_color", 1.0f);  // a float into a vec4
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("is vec4 but set() got a float"), std::string::npos) << warnings[0];
    EXPECT_EQ(program.typeMismatchReports(), std::vector<std::string>{"u_color"});
    EXPECT_TRUE(program.unknownUniformReports().empty());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));  // the bad call never reached GL
}

TEST_F(ProgramTest, RawSourcesAskTheDriverForUniforms) {
    prism::gl::ProgramSources sources;
    sources.label = "raw";
    sources.stages.push_back({prism::catalog::Stage::Vertex,
                              "#version 330 core\nin vec2 a_position;\n"
                              "void main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n",
                              {{0, "raw.vert"}}});
    sources.stages.push_back({prism::catalog::Stage::Fragment,
                              "#version 330 core\nuniform vec3 u_rgb[2];\nout vec4 c;\n"
                              "void main() { c = vec4(u_rgb[0] + u_rgb[1], 1.0); }\n",
                              {{0, "raw.frag"}}});
    sources.attributes.push_back({"a_position", 0});
    Program program(std::move(sources));
    EXPECT_TRUE(program.hasUniform("u_rgb"));
    EXPECT_TRUE(program.hasUniform("u_rgb[1]"));
    const glm::vec3 rgb[] = {{0.5f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    program.set("u_rgb", std::span<const glm::vec3>(rgb));
    std::vector<std::string> warnings;
    program.setWarningHandler([&](std::string_view m) { warnings.emplace_back(m); });
    program.set("u_rgb[1]", 1.0f);  // wrong type, learnt from the driver
    EXPECT_EQ(warnings.size(), 1u);

    prism::gl::Framebuffer fb(kSize, kSize);
    drawTriangle(fb, program);
    EXPECT_EQ(fb.readImage8().at(kSize / 2, kSize / 2), (prism::image::Rgba8{128, 0, 255, 255}));
}

}  // namespace
