// The clean-check shortcut of `prism-shaderc --check`, the run record (up_to_date.hpp) of a
// check that writes no file: after a check that found nothing, a re-check whose files
// differ only in comments and layout ends
// without validating; any code edit, a new file in a searched folder, or diagnostics from
// the last run give a full check. And the code signature it compares
// (code_signature.hpp): blind to comments and blanks, never to code.
#include <gtest/gtest.h>

#include <string>

#include "code_signature.hpp"
#include "tool_runner.hpp"

using prism::shaderc::codeSignature;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

constexpr const char* kShortcut = "no code changed since the last clean check";

void writeCatalogue(const ScratchDir& dir, const std::string& module) {
    dir.write("m/one.glsl", module);
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag", "#version 330 core\n#include \"one.glsl\"\nout vec4 o;\nvoid main() { o = vec4(one()); }\n");
}

const std::string kArgs = "--check --stats --cache-dir build/cache -I m s";

}  // namespace

TEST(CodeSignature, IgnoresCommentsBlanksAndBlankLines) {
    EXPECT_EQ(codeSignature("vec3 a; // note\n\n  float  b;\t/* x\ny */ int c;\n"), "vec3 a;\nfloat b; int c;\n");
    EXPECT_EQ(codeSignature("// Provides: f().\nfloat  f()  {\n    return 1.0;  // one\n}\n\n"),
              codeSignature("float f() {\n\treturn 1.0; /* one */\n}\n"));
}

TEST(CodeSignature, SeesEveryCodeChange) {
    const std::string base = "float f() { return 1.0; }\n";
    EXPECT_NE(codeSignature(base), codeSignature("float f() { return 2.0; }\n"));
    EXPECT_NE(codeSignature("a/**/b"), codeSignature("ab")) << "a comment separates two tokens";
    EXPECT_NE(codeSignature("#define A 1\nA"), codeSignature("#define A 1 A")) << "line structure of directives";
    EXPECT_NE(codeSignature("#define X /*\n*/ 1\n"), codeSignature("#define X\n1\n"))
        << "a comment across lines does not end a directive";
    EXPECT_NE(codeSignature("#include \"a//b.glsl\"\n"), codeSignature("#include \"a//c.glsl\"\n"))
        << "a quoted // is not a comment";
    // __LINE__ depends on line numbers: such a file is compared by its whole text.
    EXPECT_NE(codeSignature("int l = __LINE__;\n"), codeSignature("\nint l = __LINE__;\n"));
}

TEST(CodeSignature, HostileTextsEndCleanly) {
    EXPECT_EQ(codeSignature(""), "");
    EXPECT_EQ(codeSignature("/* never closed\nfloat x;"), "") << "an open comment runs to the end";
    EXPECT_EQ(codeSignature("#include \"open"), "#include \"open\n");
    EXPECT_EQ(codeSignature("a\"b\nc"), "a\"b\nc\n") << "an open quote ends at the line end";
    EXPECT_EQ(codeSignature(std::string("x\0y", 3)), std::string("x\0y\n", 4));
    const std::string huge(1 << 22, ' ');
    EXPECT_EQ(codeSignature(huge + "v" + huge), "v\n");
}

TEST(CleanCheck, ACommentEditEndsTheRecheckWithoutValidating) {
    ScratchDir dir("clean-check-comment");
    writeCatalogue(dir, "// Provides: one().\nfloat one() { return 1.0; }\n");
    auto first = runShaderc(kArgs, dir.str());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_EQ(first.output.find(kShortcut), std::string::npos) << first.output;
    dir.write("m/one.glsl", "// Provides: one(), now with a longer comment.\n\nfloat one() {  return 1.0; }\n");
    auto again = runShaderc(kArgs, dir.str());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find(kShortcut), std::string::npos) << again.output;
    auto forced = runShaderc(kArgs + " --revalidate", dir.str());
    EXPECT_NE(forced.output.find("validated"), std::string::npos) << forced.output;
}

// The safety of the shortcut: a code edit that breaks the shader is found, and stays found.
TEST(CleanCheck, ACodeEditIsCheckedAndItsErrorIsReportedEveryTime) {
    ScratchDir dir("clean-check-code");
    writeCatalogue(dir, "// Provides: one().\nfloat one() { return 1.0; }\n");
    ASSERT_EQ(runShaderc(kArgs, dir.str()).exitCode, 0);
    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return undefinedThing; }\n");
    for (int run = 0; run < 2; ++run) {
        auto broken = runShaderc(kArgs, dir.str());
        EXPECT_EQ(broken.exitCode, 1) << "run " << run << ": " << broken.output;
        EXPECT_NE(broken.output.find("undefinedThing"), std::string::npos) << broken.output;
        EXPECT_EQ(broken.output.find(kShortcut), std::string::npos) << broken.output;
    }
    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return 1.0; }\n");
    auto fixed = runShaderc(kArgs, dir.str());
    EXPECT_EQ(fixed.exitCode, 0) << fixed.output;
    EXPECT_EQ(fixed.output.find(kShortcut), std::string::npos) << "the failing run left no record";
}

// A new module in a searched folder may change what an include finds: a full check.
TEST(CleanCheck, ANewFileInASearchedFolderGivesAFullCheck) {
    ScratchDir dir("clean-check-listing");
    writeCatalogue(dir, "// Provides: one().\nfloat one() { return 1.0; }\n");
    ASSERT_EQ(runShaderc(kArgs, dir.str()).exitCode, 0);
    dir.write("m/two.glsl", "// Provides: two().\nfloat two() { return 2.0; }\n");
    auto again = runShaderc(kArgs, dir.str());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(again.output.find(kShortcut), std::string::npos) << again.output;
}

// Warnings are printed by every run, so a run with one records nothing.
TEST(CleanCheck, AWarningIsPrintedAgainByTheNextCheck) {
    ScratchDir dir("clean-check-warning");
    writeCatalogue(dir, "float one() { return 1.0; }\n");  // no leading comment: a warning
    for (int run = 0; run < 2; ++run) {
        auto r = runShaderc(kArgs, dir.str());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("warning:"), std::string::npos) << "run " << run << ": " << r.output;
    }
}

TEST(CleanCheck, RevalidateWithoutCheckIsAUsageError) {
    ScratchDir dir("clean-check-usage");
    writeCatalogue(dir, "// Provides: one().\nfloat one() { return 1.0; }\n");
    auto r = runShaderc("--revalidate -o h.hpp -I m s", dir.str());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--revalidate only changes --check"), std::string::npos) << r.output;
}
