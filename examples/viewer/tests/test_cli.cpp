// The viewer's command line without a display (CTest unsets DISPLAY): --help and --version
// exit 0 and print the usage and the version; bad values, a missing scene, an axis or axis
// value the shader lacks, a stray argument, a misspelled option and --source-root without
// --watch are usage errors (exit 2, a "viewer: error:" line). One test per case (prism/test/cli_case.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prism/test/cli_case.hpp"

namespace {

prism::test::CliCase usageError(const std::string& name, std::vector<std::string> args) {
    return {.name = name,
            .program = "viewer",
            .args = std::move(args),
            .exitCode = 2,
            .errText = "",
            .files = {},
            .needs = "",
            .outRegex = "",
            .errRegex = "(^|\n)viewer: error: "};
}

std::vector<prism::test::CliCase> cases() {
    std::vector<prism::test::CliCase> cases = {
        {.name = "help",
         .program = "viewer",
         .args = {"--help"},
         .exitCode = 0,
         .errText = "",
         .files = {},
         .needs = "",
         .outRegex = "(^|\n)Usage: viewer[\\s\\S]*--scene",
         .errRegex = ""},
        {.name = "version",
         .program = "viewer",
         .args = {"--version"},
         .exitCode = 0,
         .errText = "",
         .files = {},
         .needs = "",
         .outRegex = "^viewer \\(Prism\\) [0-9]",
         .errRegex = ""},
        {.name = "rejects_unknown_option",
         .program = "viewer",
         .args = {"--frmaes", "5"},
         .exitCode = 2,
         .errText = "",
         .files = {},
         .needs = "",
         .outRegex = "",
         .errRegex = "viewer: error: .*--frmaes"},
        usageError("rejects_negative_frames", {"--frames", "-1"}),
        usageError("rejects_subdivision_9", {"--subdivision", "9"}),
        usageError("rejects_missing_scene", {"--scene", "/nonexistent.json"}),
        usageError("rejects_axis_without_value", {"--variant", "BLINN"}),
        usageError("rejects_unknown_shader", {"--shader", "nosuch"}),
        usageError("rejects_unknown_mesh", {"--mesh", "nosuch"}),
        usageError("rejects_stray_argument", {"extra"}),
        usageError("rejects_unknown_axis_value", {"--variant", "BLINN=7"}),
        usageError("rejects_axis_the_shader_lacks", {"--shader", "gouraud", "--variant", "BLINN=1"}),
        {.name = "rejects_source_root_without_watch",
         .program = "viewer",
         .args = {"--source-root", "/tmp"},
         .exitCode = 2,
         .errText = "",
         .files = {},
         .needs = "",
         .outRegex = "",
         .errRegex = "viewer: error: --source-root requires --watch"},
    };
    return cases;
}

const prism::test::CliSuite kSuite{
    .root = PRISM_VIEWER_TEST_TMP, .apps = {{"viewer", PRISM_VIEWER}}, .cases = cases(), .scenes = ""};

class ViewerCli : public ::testing::TestWithParam<prism::test::CliCase> {};

TEST_P(ViewerCli, Case) {
    prism::test::checkCliCase(kSuite, GetParam());
}

INSTANTIATE_TEST_SUITE_P(, ViewerCli, ::testing::ValuesIn(prism::test::runnableCases(kSuite)), prism::test::caseName);

}  // namespace
