// Module libraries found through -I outside --base-dir (fixtures/library_layout: lygia's
// layout, with each module's documentation comment after its includes): the "module has
// no leading comment" warning is the project's, so it is off for them unless
// --warn-undocumented-modules all asks, and without it a library keeps the clean-check
// shortcut (the run record, up_to_date.hpp). Modules under --base-dir keep the warning, -I or not.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using prism::test::occurrences;
using prism::test::runShaderc;
using prism::test::ScratchDir;

const std::string kFixture = std::string(PRISM_SOURCE_DIR) + "/tests/shaderc/fixtures/library_layout";
constexpr const char* kWarning = "module has no leading comment saying what it provides";
constexpr const char* kShortcut = "no code changed since the last clean check";

// The fixture in a scratch folder, so checks can write their cache beside it.
void copyFixture(const ScratchDir& dir) {
    fs::copy(kFixture, dir.path(), fs::copy_options::recursive);
}

TEST(LibraryModules, ALibraryOutsideTheBaseDirGetsNoCommentWarning) {
    ScratchDir dir("library-quiet");
    copyFixture(dir);
    const auto run = runShaderc("--check --base-dir project -I lib project/shaders", dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("warning:"), std::string::npos) << run.output;
}

TEST(LibraryModules, WarnUndocumentedModulesAllWarnsForTheLibraryToo) {
    ScratchDir dir("library-all");
    copyFixture(dir);
    const auto run =
        runShaderc("--check --warn-undocumented-modules all --base-dir project -I lib project/shaders", dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(occurrences(run.output, kWarning), 2u) << "luma.glsl and desaturate.glsl:\n" << run.output;
    EXPECT_NE(run.output.find("lib/color/luma.glsl:1:1: warning: "), std::string::npos) << run.output;
}

// The same library under --base-dir is the project's own: warned, through -I as before.
TEST(LibraryModules, ModulesUnderTheBaseDirKeepTheWarning) {
    ScratchDir dir("library-inside");
    copyFixture(dir);
    const auto run = runShaderc("--check -I lib project/shaders", dir.str());  // --base-dir: the scratch folder
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(occurrences(run.output, kWarning), 2u) << run.output;
}

TEST(LibraryModules, AnUnknownWarnUndocumentedModulesValueIsAUsageError) {
    const auto run = runShaderc("--check --warn-undocumented-modules some x.frag");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--warn-undocumented-modules"), std::string::npos) << run.output;
}

// With the warning gone, a check of a project using the library finds nothing, so the next
// check of unchanged code takes the shortcut; with the warning on, it never does.
TEST(LibraryModules, ALibraryOutsideTheBaseDirKeepsTheCleanCheckShortcut) {
    ScratchDir dir("library-clean-check");
    copyFixture(dir);
    const std::string args = "--check --stats --cache-dir cache --base-dir project -I lib project/shaders";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto again = runShaderc(args, dir.str());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find(kShortcut), std::string::npos) << again.output;

    const std::string all = "--check --warn-undocumented-modules all " + args.substr(8);
    for (int run = 0; run < 2; ++run) {
        const auto warned = runShaderc(all, dir.str());
        EXPECT_EQ(warned.exitCode, 0) << warned.output;
        EXPECT_EQ(warned.output.find(kShortcut), std::string::npos) << "run " << run << ":\n" << warned.output;
        EXPECT_NE(warned.output.find(kWarning), std::string::npos) << "run " << run << ":\n" << warned.output;
    }
}

}  // namespace
