// Variants that cannot differ share one resolution (variant_resolution.hpp): the output
// must be byte-identical to resolving every variant on its own
// (PRISM_SHADERC_NO_VARIANT_SHARING=1), for the whole project catalogue, and a macro
// met only in a file that another value of an axis includes must still count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
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
    ::setenv("PRISM_SHADERC_NO_VARIANT_SHARING", "1", 1);
    auto own = runShaderc(args, (dir.path() / "own").string());
    ::unsetenv("PRISM_SHADERC_NO_VARIANT_SHARING");
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
    dir.write("s/a.frag", "#version 330 core\n#pragma prism variant A\n#if A\n#include \"a_on.glsl\"\n#endif\n"
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
    // The vertex stage meets only B: A=1 shares A=0's run (2 of 4 vertex variants), and so
    // does the fragment stage's B=1 with B=0 when A=0 (1 of 4).
    auto stats = runShaderc("--check --stats --cache-dir none s", dir.str());
    EXPECT_NE(stats.output.find("resolved 5 of 8 stages with glslang (3 shared another variant's run)"),
              std::string::npos)
        << stats.output;
}

// `##` can build a macro's name from pieces: a file that pastes tokens is never
// trusted to be free of an axis (here the pasted MYAXIS changes the token stream, so
// the two variants must not share one).
TEST(VariantSharing, TokenPastingDisablesSharing) {
    ScratchDir dir("variant-sharing-paste");
    dir.write("s/a.vert", "#version 330 core\n#pragma prism variant MYAXIS\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag", "#version 330 core\n#define CAT(x, y) x##y\nout vec4 o;\n"
                          "void main() { o = vec4(float(CAT(MY, AXIS))); }\n");
    auto run = runShaderc("--check --stats --emit-glsl out --cache-dir none s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("validated 2 of 2 programs (0 shared a token stream"), std::string::npos) << run.output;
}
