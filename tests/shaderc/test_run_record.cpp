// The one record of "nothing changed" (up_to_date.hpp) for a run that writes every kind of
// output: the header and data file, the web catalogue, the emitted GLSL, the depfile and the
// stamp. Its second run ends before resolving; an edit of an included module, another
// option, and an output deleted or edited by hand each give a full run that restores it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

const std::string kEveryOutput =
    "-o gen/out.hpp --emit-glsl gen/glsl --emit-web gen/web.js --target gl,es300 --depfile gen/out.d --stamp "
    "gen/out.stamp --stats -I m s";

void writeCatalogue(const ScratchDir& dir) {
    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return 1.0; }\n");
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag", "#version 330 core\n#include \"one.glsl\"\nout vec4 o;\nvoid main() { o = vec4(one()); }\n");
}

// A full run prints its --stats resolution line; the record's no-op prints nothing.
bool fullRun(const ScratchDir& dir, const std::string& args = kEveryOutput) {
    const auto run = runShaderc(args, dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return run.output.find("resolved ") != std::string::npos;
}

std::string emittedGlsl(const ScratchDir& dir) {
    for (const auto& entry : fs::directory_iterator(dir.path() / "gen/glsl")) return entry.path().string();
    return {};
}

}  // namespace

TEST(RunRecord, AnEveryOutputRunIsANoOpTheSecondTime) {
    ScratchDir dir("record-every-output");
    writeCatalogue(dir);
    ASSERT_TRUE(fullRun(dir));
    const std::string web = readFile(dir.path() / "gen/web.js");
    ASSERT_FALSE(web.empty());
    fs::remove(dir.path() / "gen/out.d");
    EXPECT_FALSE(fullRun(dir)) << "the second run of an unchanged catalogue resolved it again";
    EXPECT_NE(readFile(dir.path() / "gen/out.d").find("one.glsl"), std::string::npos) << "the no-op writes the depfile";
    EXPECT_EQ(readFile(dir.path() / "gen/web.js"), web);
}

TEST(RunRecord, AModuleEditOrAnotherOptionGivesAFullRun) {
    ScratchDir dir("record-inputs");
    writeCatalogue(dir);
    ASSERT_TRUE(fullRun(dir));
    dir.write("m/one.glsl", "// Provides: one(), edited.\nfloat one() { return 1.0; }\n");
    EXPECT_TRUE(fullRun(dir)) << "an edit of an included module was not seen";
    EXPECT_NE(readFile(dir.path() / "gen/web.js").find("edited"), std::string::npos);
    EXPECT_FALSE(fullRun(dir));
    EXPECT_TRUE(fullRun(dir, kEveryOutput + " -D EXTRA=1")) << "another -D was not seen";
    EXPECT_FALSE(fullRun(dir, kEveryOutput + " -D EXTRA=1"));
    EXPECT_TRUE(fullRun(dir, kEveryOutput + " --glsl-version 450")) << "another --glsl-version was not seen";
}

TEST(RunRecord, AnOutputDeletedOrEditedByHandIsWrittenAgain) {
    ScratchDir dir("record-outputs");
    writeCatalogue(dir);
    ASSERT_TRUE(fullRun(dir));
    const std::string web = readFile(dir.path() / "gen/web.js");
    const std::string glslPath = emittedGlsl(dir);
    const std::string glsl = readFile(glslPath);
    const std::string data = readFile(dir.path() / "gen/out.cpp");
    fs::remove(dir.path() / "gen/web.js");
    EXPECT_TRUE(fullRun(dir)) << "a deleted web catalogue was not written again";
    EXPECT_EQ(readFile(dir.path() / "gen/web.js"), web);
    prism::test::writeFile(glslPath, "// edited by hand\n");
    EXPECT_TRUE(fullRun(dir)) << "an emitted GLSL file edited by hand was trusted";
    EXPECT_EQ(readFile(glslPath), glsl);
    prism::test::writeFile(dir.path() / "gen/out.cpp", "// edited by hand\n");
    EXPECT_TRUE(fullRun(dir)) << "a data file edited by hand was trusted";
    EXPECT_EQ(readFile(dir.path() / "gen/out.cpp"), data);
    EXPECT_FALSE(fullRun(dir));
}
