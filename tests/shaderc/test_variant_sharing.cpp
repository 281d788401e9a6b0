// Variants that cannot differ share one resolution (variant_resolution.hpp): the output
// must be byte-identical to resolving every variant on its own
// (--no-variant-sharing), for the whole project catalogue, and a macro
// met only in a file that another value of an axis includes must still count.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>
#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

std::string treeText(const fs::path& dir) {
    std::string all;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) all += "== " + f.filename().string() + "\n" + readFile(f);
    return all;
}

}  // namespace

TEST(VariantSharing, ProjectCatalogueIsByteIdenticalWithAndWithoutSharing) {
    ScratchDir dir("variant-sharing");
    const std::string source = PRISM_SOURCE_DIR;
    const std::string args = "--emit-glsl glsl -o h.hpp --cache-dir none --base-dir " + source + " -I " + source +
                             "/modules --contract " + source + "/modules/contract.json " + source + "/shader_sources";
    fs::create_directories(dir.path() / "shared");
    fs::create_directories(dir.path() / "own");
    auto shared = runShaderc(args, (dir.path() / "shared").string());
    ASSERT_EQ(shared.exitCode, 0) << shared.output;
    auto own = runShaderc("--no-variant-sharing " + args, (dir.path() / "own").string());
    ASSERT_EQ(own.exitCode, 0) << own.output;
    const std::string a = treeText(dir.path() / "shared/glsl"), b = treeText(dir.path() / "own/glsl");
    EXPECT_GT(a.size(), 100000u);
    EXPECT_TRUE(a == b) << "emitted GLSL differs with variant sharing";
    EXPECT_TRUE(readFile(dir.path() / "shared/h.hpp") == readFile(dir.path() / "own/h.hpp"));
}

TEST(VariantSharing, AMacroMetOnlyUnderAnotherAxisStillCounts) {
    ScratchDir dir("variant-sharing-nested");
    // B is declared in the vertex stage; in the fragment stage it is met only inside
    // a_on.glsl, which only A=1 includes.
    dir.write("s/a.vert", "#version 330 core\n#pragma prism variant B\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#pragma prism variant A\n#if A\n#include \"a_on.glsl\"\n#endif\n"
              "out vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    dir.write("s/a_on.glsl", "// Provides: the A part.\n#if B\n#include \"b_on.glsl\"\n#endif\n");
    dir.write("s/b_on.glsl", "// Provides: the B part.\nfloat bPart() { return 2.0; }\n");
    auto run = runShaderc("--check --emit-glsl out --cache-dir none s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string both = readFile(dir.path() / "out/a.B-1_A-1.frag");
    const std::string onlyA = readFile(dir.path() / "out/a.B-0_A-1.frag");
    ASSERT_FALSE(both.empty()) << "no out/a.B-1_A-1.frag";
    EXPECT_NE(both.find("float bPart()"), std::string::npos) << both;
    EXPECT_EQ(onlyA.find("float bPart()"), std::string::npos) << onlyA;
    EXPECT_NE(both.find("#define B 1"), std::string::npos) << both;
    EXPECT_NE(readFile(dir.path() / "out/a.B-1_A-0.frag").find("#define B 1"), std::string::npos);
    // One base run per stage finds the axes. Nothing in the vertex stage's files decides an
    // include, so its 4 variants share its base run. The fragment stage runs once per value
    // of A (A decides an include); B=1 with A=0 shares B=0's run (B decides nothing there),
    // but B=1 with A=1 runs on its own (in a_on.glsl, B decides an include): 2 + 3 runs.
    auto stats = runShaderc("--check --stats --cache-dir none s", dir.str());
    EXPECT_NE(stats.output.find("resolved 8 stages with 5 runs of glslang's preprocessor (5 shared another run)"),
              std::string::npos)
        << stats.output;
}

// `##` can build a macro's name from pieces: a file that pastes tokens is never
// trusted to be free of an axis (here the pasted MYAXIS changes the token stream, so
// the two variants must not share one).
TEST(VariantSharing, TokenPastingDisablesSharing) {
    ScratchDir dir("variant-sharing-paste");
    dir.write("s/a.vert",
              "#version 330 core\n#pragma prism variant MYAXIS\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#define CAT(x, y) x##y\nout vec4 o;\n"
              "void main() { o = vec4(float(CAT(MY, AXIS))); }\n");
    auto run = runShaderc("--check --stats --emit-glsl out --cache-dir none s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("validated 2 of 2 programs (0 shared a token stream"), std::string::npos) << run.output;
}

// Sharing against every variant's own glslang run, on structures that decide includes
// in roundabout ways: a condition that defines a macro another condition tests, #ifdef
// of an axis, an axis only in code, an axis whose values name macros of the files, and
// an include under an axis inside an include guard. The emitted GLSL must be
// byte-identical, with fewer glslang runs.
TEST(VariantSharing, RoundaboutStructuresMatchEveryVariantsOwnRun) {
    ScratchDir dir("variant-sharing-roundabout");
    dir.write("s/a.vert",
              "#version 330 core\n#pragma prism variant K ONE TWO\n#include \"m/values.glsl\"\n"
              "void main() { gl_Position = vec4(float(K)); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#pragma prism variant Q 0 1 2\n#pragma prism variant CODE\n"
              "#pragma prism variant D\n#include \"m/chain.glsl\"\n#include \"m/guarded.glsl\"\n"
              "out vec4 o;\nvoid main() { o = vec4(chain() + guarded() + float(CODE)); }\n");
    dir.write("s/m/values.glsl", "// Provides: the values of K.\n#define ONE 1\n#define TWO 2\n");
    dir.write("s/m/chain.glsl",
              "// Provides: chain().\n#if Q == 1\n#define USE_X\n#endif\n#ifdef USE_X\n"
              "#include \"x.glsl\"\n#else\nfloat chain() { return 0.0; }\n#endif\n");
    dir.write("s/m/x.glsl", "// Provides: the X chain.\nfloat chain() { return 1.0; }\n");
    dir.write("s/m/guarded.glsl",
              "// Provides: guarded().\n#ifndef GUARDED\n#define GUARDED\n#if D\n"
              "#include \"d.glsl\"\n#endif\nfloat guarded() {\n#if D\n  return d();\n#else\n"
              "  return 0.0;\n#endif\n}\n#endif\n");
    dir.write("s/m/d.glsl", "// Provides: d().\nfloat d() { return 2.0; }\n");
    const std::string args = "--check --stats --cache-dir none s --emit-glsl ";
    auto shared = runShaderc(args + "shared", dir.str());
    auto own = runShaderc("--no-variant-sharing " + args + "own", dir.str());
    ASSERT_EQ(shared.exitCode, 0) << shared.output;
    ASSERT_EQ(own.exitCode, 0) << own.output;
    const std::string a = treeText(dir.path() / "shared"), b = treeText(dir.path() / "own");
    EXPECT_TRUE(a == b) << "emitted GLSL differs with variant sharing:\n" << a << "\n----\n" << b;
    EXPECT_NE(a.find("return 1.0;"), std::string::npos);  // Q=1 took x.glsl
    EXPECT_NE(a.find("float d()"), std::string::npos);    // D=1 took d.glsl
    // K (2 values) x Q (3) x CODE (2) x D (2) = 24 variants, 48 stages; without sharing
    // each runs, plus the two base runs: 50. With it, the two base runs, then the vertex
    // stage once per value of K (its values name macros of values.glsl) and the fragment
    // stage once per value of Q and D, its structural macros (CODE is only in code):
    // 2 + 2 + 3 x 2 = 10.
    EXPECT_NE(own.output.find("resolved 48 stages with 50 runs"), std::string::npos) << own.output;
    EXPECT_NE(shared.output.find("resolved 48 stages with 10 runs"), std::string::npos) << shared.output;
}

// The preprocessor limits (preprocessor_limits.hpp) are checked in each glslang run: a
// variant whose axis value names a macro of the files expands that macro where the axis
// is used, so it never shares a run checked with another value. Here E=HUGE names a
// 4-million-token macro: the limit must stop it, with sharing as without.
TEST(VariantSharing, AnAxisValueNamingAMacroIsCheckedInItsOwnRun) {
    ScratchDir dir("variant-sharing-limits");
    std::string chain = "// Provides: HUGE, 2^22 tokens.\n#define M0 1\n";
    for (int i = 1; i <= 22; ++i)
        chain += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " + M" + std::to_string(i - 1) + "\n";
    chain += "#define SMALL 1\n#define HUGE M22\n";
    dir.write("s/m/values.glsl", chain);
    dir.write("s/a.vert",
              "#version 330 core\n#pragma prism variant E SMALL HUGE\n#include \"m/values.glsl\"\n"
              "void main() { gl_Position = vec4(float(E)); }\n");
    dir.write("s/a.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    for (const bool share : {true, false}) {
        const std::string sharing = share ? "" : "--no-variant-sharing ";
        auto run = runShaderc(sharing + "--check --cache-dir none s", dir.str());
        EXPECT_EQ(run.exitCode, 1) << "sharing " << share << ":\n" << run.output;
        EXPECT_NE(run.output.find("expand to more than 1,000,000 tokens"), std::string::npos)
            << "sharing " << share << ":\n"
            << run.output;
    }
}
