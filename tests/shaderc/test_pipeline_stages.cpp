// prism-shaderc's stages as main() sequences them (main.cpp): a usage error found by the
// command-line stage stops the run before anything is read or written, and the up-to-date
// stage (up_to_date.hpp) ends a repeated run before resolution, writing only the depfile.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

void writeValidShader(const ScratchDir& dir) {
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
}

}  // namespace

TEST(PipelineStages, AHeaderNamedLikeItsDataFileIsAUsageError) {
    ScratchDir dir("stages-data-path");
    writeValidShader(dir);
    auto run = runShaderc("-o out.cpp s", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("prism-shaderc: error: -o out.cpp: the data file would overwrite the header; name the "
                              "header .hpp or .h"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out.cpp"));
}

TEST(PipelineStages, ARepeatedRunEndsBeforeResolutionAndWritesTheDepfile) {
    ScratchDir dir("stages-up-to-date");
    writeValidShader(dir);
    const std::string args = "-o out.hpp --depfile out.d --stats --cache-dir none s";
    auto first = runShaderc(args, dir.str());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("prism-shaderc: resolved "), std::string::npos) << first.output;
    fs::remove(dir.path() / "out.d");
    auto again = runShaderc(args, dir.str());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(again.output, "") << "nothing resolved, validated or reported";
    EXPECT_NE(readFile(dir.path() / "out.d").find("s/a.frag"), std::string::npos);
}
