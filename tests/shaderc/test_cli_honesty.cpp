// prism-shaderc's command line says what it does (issue 10 item 5): unknown options
// are named, flag combinations that would silently ignore a flag are usage errors
// (exit 2) naming both flags or do what they say (--check --emit-glsl emits and checks),
// and each warning is printed once.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::occurrences;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

// A valid two-stage shader `a` in s/, including m/util.glsl.
void writeValidShader(const ScratchDir& dir) {
    dir.write("m/util.glsl", "// Provides: tint().\nvec3 tint() { return vec3(0.5); }\n");
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#include \"util.glsl\"\nout vec4 o;\nvoid main() { o = vec4(tint(), 1.0); }\n");
}

}  // namespace

TEST(CliHonesty, UnknownOptionIsNamedNotAMissingInput) {
    for (std::string option : {"--bogus", "-x", "--chek"}) {
        auto run = runShaderc(option);
        EXPECT_EQ(run.exitCode, 2) << option << ": " << run.output;
        EXPECT_NE(run.output.find("unknown option '" + option + "'"), std::string::npos) << run.output;
        EXPECT_EQ(run.output.find("required"), std::string::npos) << run.output;
    }
    auto withInput = runShaderc("--check --bogus s");
    EXPECT_EQ(withInput.exitCode, 2);
    EXPECT_NE(withInput.output.find("unknown option '--bogus'"), std::string::npos) << withInput.output;
}

TEST(CliHonesty, NoInputsSaysSo) {
    auto run = runShaderc("--check");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("no shader inputs"), std::string::npos) << run.output;
}

TEST(CliHonesty, CheckWithHeaderIsAConflictNamingBoth) {
    ScratchDir dir("cli-check-o");
    writeValidShader(dir);
    auto run = runShaderc("--check -o out.hpp -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--check"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("-o out.hpp"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out.hpp"));
}

TEST(CliHonesty, DepfileWithoutATargetIsAConflict) {
    ScratchDir dir("cli-depfile");
    writeValidShader(dir);
    auto run = runShaderc("--check --depfile out.d -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--depfile out.d needs a target"), std::string::npos) << run.output;
    // With a stamp it does what it says, under --check too.
    auto stamped = runShaderc("--check --depfile out.d --stamp out.stamp -I m s", dir.str());
    EXPECT_EQ(stamped.exitCode, 0) << stamped.output;
    EXPECT_TRUE(fs::exists(dir.path() / "out.stamp"));
    const std::string dep = prism::test::readFile(dir.path() / "out.d");
    EXPECT_EQ(dep.rfind("out.stamp:", 0), 0u) << dep;
    EXPECT_NE(dep.find("util.glsl"), std::string::npos) << dep;
}

TEST(CliHonesty, NamespaceWithoutHeaderIsAConflict) {
    ScratchDir dir("cli-ns");
    writeValidShader(dir);
    auto run = runShaderc("--check --namespace my::ns -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--namespace"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("no header is written"), std::string::npos) << run.output;
}

TEST(CliHonesty, CheckWithEmitGlslEmitsAndChecks) {
    ScratchDir dir("cli-check-emit");
    writeValidShader(dir);
    auto run = runShaderc("--check --emit-glsl out -I m s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir.path() / "out/a.vert"));
    EXPECT_TRUE(fs::exists(dir.path() / "out/a.frag"));
    // ... and it still checks: an error writes nothing.
    dir.write("s/a.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(missing, 1.0); }\n");
    fs::remove_all(dir.path() / "out");
    auto bad = runShaderc("--check --emit-glsl out -I m s", dir.str());
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_NE(bad.output.find("'missing'"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out/a.frag"));
}

// A module without its leading comment, included by two shaders with two variants each,
// under two spellings of its path, and a module error that fails both stages: the
// warning is printed once and the failing module is not also called unused.
TEST(CliHonesty, EachWarningIsPrintedOnce) {
    ScratchDir dir("cli-warn-once");
    dir.write("m/nocomment.glsl", "vec3 f() { return vec3(1.0); }\n");
    dir.write("m/broken.glsl",
              "// Provides: g(), which includes a file that is not there.\n"
              "#include \"not_there.glsl\"\nvec3 g() { return vec3(1.0); }\n");
    for (std::string s : {"a", "b"}) {
        dir.write("s/" + s + ".vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
        dir.write("s/" + s + ".frag", "#version 330 core\n#pragma prism variant FOG\n#include \"" +
                                          std::string(s == "a" ? "nocomment.glsl" : "../m/nocomment.glsl") +
                                          "\"\nout vec4 o;\nvoid main() { o = vec4(f(), 1.0); }\n");
    }
    auto good = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(good.exitCode, 0) << good.output;
    EXPECT_EQ(occurrences(good.output, "module has no leading comment"), 1u) << good.output;

    dir.write("s/c.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/c.frag",
              "#version 330 core\n#include \"broken.glsl\"\nout vec4 o;\nvoid main() { o = vec4(g(), 1.0); }\n");
    auto bad = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_EQ(occurrences(bad.output, "module has no leading comment"), 1u) << bad.output;
    EXPECT_EQ(occurrences(bad.output, "cannot find include \"not_there.glsl\""), 1u) << bad.output;
    EXPECT_EQ(bad.output.find("which no stage includes"), std::string::npos) << bad.output;
}
