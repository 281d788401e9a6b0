// Diagnostics of prism-shaderc (issue 10 item 6): a syntax error gets the column of
// the token glslang names, else the first non-blank column of its line (glslang 12
// gives no columns); no double space after "error:"; "did you mean" for a function no
// module of the stage defines and for an include name no search folder holds.
#include <gtest/gtest.h>

#include <string>

#include "did_you_mean.hpp"
#include "tool_runner.hpp"

using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

void writeShader(const ScratchDir& dir, const std::string& fragmentBody) {
    dir.write("m/util.glsl",
              "// Provides: tint() and lightng(), a deliberately odd name.\n"
              "vec3 tint(vec3 c) { return c * 0.5; }\n"
              "float lightng(float x) { return x; }\n");
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#include \"util.glsl\"\nout vec4 o;\nvoid main() {\n" + fragmentBody + "}\n");
}

}  // namespace

TEST(DiagnosticHints, SyntaxErrorGetsTheFirstNonBlankColumnAndOneSpace) {
    ScratchDir dir("diag-syntax");
    writeShader(dir, "    float x = 1.0\n      o = vec4(tint(vec3(x)), 1.0);\n");
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    // glslang: "0:6: '' :  syntax error, unexpected IDENTIFIER" (the `o` of line 6).
    EXPECT_NE(run.output.find("s/a.frag:6:7: error: syntax error, unexpected IDENTIFIER"), std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("error:  "), std::string::npos) << run.output;
}

TEST(DiagnosticHints, TokenColumnWhenGlslangNamesOne) {
    ScratchDir dir("diag-token");
    writeShader(dir, "    float x = 1.0 + 2.0 * undefinedThing;\n    o = vec4(x);\n");
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("s/a.frag:5:27: error: 'undefinedThing': undeclared identifier"), std::string::npos)
        << run.output;
}

TEST(DiagnosticHints, DidYouMeanForAnUndefinedFunction) {
    ScratchDir dir("diag-function");
    writeShader(dir, "    float x = lighting(1.0);\n    o = vec4(x);\n");
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("s/a.frag:5:15: error: 'lighting': no matching overloaded function found (did you "
                              "mean 'lightng'?)"),
              std::string::npos)
        << run.output;
    // A function that exists, called with the wrong arguments: no hint.
    writeShader(dir, "    o = vec4(tint(1.0, 2.0), 1.0);\n");
    auto wrongArgs = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(wrongArgs.exitCode, 1);
    EXPECT_NE(wrongArgs.output.find("'tint': no matching overloaded function found"), std::string::npos)
        << wrongArgs.output;
    EXPECT_EQ(wrongArgs.output.find("did you mean"), std::string::npos) << wrongArgs.output;
}

TEST(DiagnosticHints, DidYouMeanForAMissingInclude) {
    ScratchDir dir("diag-include");
    writeShader(dir, "    o = vec4(1.0);\n");
    dir.write("m/color/space.glsl", "// Provides: nothing much.\n");
    dir.write("s/a.frag",
              "#version 330 core\n#include \"utl.glsl\"\n#include <color/spce.glsl>\nout vec4 o;\n"
              "void main() { o = vec4(1.0); }\n");
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("s/a.frag:2:10: error: cannot find include \"utl.glsl\" (did you mean \"util.glsl\"?)"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("cannot find include <color/spce.glsl> (did you mean <color/space.glsl>?)"),
              std::string::npos)
        << run.output;
}

TEST(DiagnosticHints, FunctionNamesAndClosestName) {
    const auto names = prism::shaderc::functionNamesIn(
        "// vec3 commented(vec3 x) {\nvec3 tint(vec3 c) { return c; }\nhighp float lightng(float x)\n{\n"
        "    return sqrt(x);\n}\nvoid main() {\n    if (x) foo();\n}\n/* float hidden(\n*/\n");
    EXPECT_EQ(names, (std::vector<std::string>{"lightng", "main", "tint"}));
    EXPECT_EQ(prism::shaderc::closestName("tnt", {"tint", "main"}), "tint");
    EXPECT_EQ(prism::shaderc::closestName("abc", {"xyz"}), "");    // too far
    EXPECT_EQ(prism::shaderc::closestName("tint", {"tint"}), "");  // never the name itself
}
