// The one `#line` rule (prism/catalog/line_directive.hpp), checked against glslang for
// #version 100, 300 es, 330 and 450: a directive made by the helper must make glslang
// report the very line the helper meant. Then a `#version 300 es` shader through the
// tool: it validates, and an error inside its module comes back at the module's own
// line and column (the resolver writes and the validator reads `#line` by this rule).
#include <gtest/gtest.h>

#include <prism/catalog/line_directive.hpp>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::catalog::glslVersionOf;
using prism::catalog::lineDirective;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

std::string runGlslangValidator(const fs::path& file) {
    return prism::test::runCommand({"glslangValidator", file.string()}, {.workDir = {}, .mergeStderr = true}).out;
}

}  // namespace

TEST(LineDirective, ReadsVersionDirectives) {
    EXPECT_EQ(glslVersionOf("#version 100").number, 100);
    EXPECT_TRUE(glslVersionOf("#version 100").es);
    EXPECT_TRUE(glslVersionOf("#version 300 es").es);
    EXPECT_TRUE(glslVersionOf("  #  version 310 es\r").es);
    EXPECT_FALSE(glslVersionOf("#version 330 core").es);
    EXPECT_FALSE(glslVersionOf("#version 150 compatibility").es);
    EXPECT_EQ(glslVersionOf("#version 450").number, 450);
    EXPECT_EQ(glslVersionOf("no version").number, 0);
}

// Differential: glslang is the reference for what the line after `#line` is.
TEST(LineDirective, GlslangReportsTheLineTheHelperMeant) {
    ScratchDir dir("line-directive");
    const char* versions[] = {"#version 100", "#version 300 es", "#version 150", "#version 330 core",
                              "#version 450 core"};
    for (const char* directive : versions) {
        const auto version = glslVersionOf(directive);
        for (int target : {1, 7, 40}) {
            std::string text = std::string(directive) + "\n";
            if (version.es) text += "precision mediump float;\n";
            text += lineDirective(target, 3, version) + "\n";
            text += "float broken() { return undeclared_thing_here; }\n";
            text += "void main() {}\n";
            const fs::path file = dir.path() / "probe.frag";
            prism::test::writeFile(file, text);
            const std::string log = runGlslangValidator(file);
            const std::string expected = "ERROR: 3:" + std::to_string(target) + ": 'undeclared_thing_here'";
            EXPECT_NE(log.find(expected), std::string::npos)
                << directive << ", line " << target << ": expected \"" << expected << "\"\n"
                << text << "---\n"
                << log;
        }
    }
}

TEST(LineDirective, GlslEs300StageThroughTheTool) {
    ScratchDir dir("line-es300");
    dir.write("m/shade.glsl",
              "// Provides: shade(x), scaled.\n"
              "float shade(float x) {\n"
              "    float y = x;\n"
              "    return y * SCALE;\n"
              "}\n");
    dir.write("s/es.vert",
              "#version 300 es\nin vec3 a_position;\nvoid main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("s/es.frag",
              "#version 300 es\nprecision mediump float;\n#define SCALE 2.0\n#include \"shade.glsl\"\n"
              "out vec4 o;\nvoid main() { o = vec4(shade(0.5)); }\n");
    auto good = runShaderc("--check --emit-glsl out -I m s", dir.str());
    ASSERT_EQ(good.exitCode, 0) << good.output;
    const std::string flat = prism::test::readFile(dir.path() / "out/es.frag");
    EXPECT_EQ(flat.rfind("#version 300 es\n", 0), 0u) << flat;
    EXPECT_NE(flat.find("#line 1 1\n// Provides: shade"), std::string::npos) << flat;  // ES: next line is N

    // The error sits on line 4 of the module, column 16; line 3 has no such token, so a
    // `#line` off by one gives another line (and column) or none.
    dir.write("s/es.frag",
              "#version 300 es\nprecision mediump float;\n#include \"shade.glsl\"\n"
              "out vec4 o;\nvoid main() { o = vec4(shade(0.5)); }\n");
    auto bad = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_NE(bad.output.find("m/shade.glsl:4:16: error: 'SCALE': undeclared identifier"), std::string::npos)
        << bad.output;
}
