// Table-driven checks of command-line programs, on runCommand: a case is a program, its
// arguments and what must come of them (exit status, messages, files). The apps' CLI suites
// and the flags check (tests/flags) are such tables, one test per case.
//
//     #include "prism/test/cli_case.hpp"
//
//     const prism::test::CliSuite kSuite{.root = PRISM_TEST_TMP, .apps = {{"prism-bluenoise", PRISM_BLUENOISE_CLI}},
//         .cases = {{.name = "usage_bogus", .program = "prism-bluenoise generate", .args = {"--bogus"},
//                    .exitCode = 2, .errText = "--bogus"}}};
//     class Cli : public ::testing::TestWithParam<prism::test::CliCase> {};
//     TEST_P(Cli, Case) { prism::test::checkCliCase(kSuite, GetParam()); }
//     INSTANTIATE_TEST_SUITE_P(, Cli, ::testing::ValuesIn(prism::test::runnableCases(kSuite)), prism::test::caseName);
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "prism/test/run_command.hpp"

namespace prism::test {

// In args and files: {T} is the case's own fresh folder (also its working directory), {D}
// the path {T}/out (a folder, or a file prefix: {D}.png) and {S} the suite's `scenes`.
struct CliCase {
    std::string name;     // the test's name: letters, digits, _
    std::string program;  // an app of the suite, then maybe a subcommand: "prism-bluenoise render"
    std::vector<std::string> args;
    int exitCode = 0;                // 2: a usage error, which must also write nothing named {D}*
    std::string errText;             // stderr contains it
    std::vector<std::string> files;  // exist afterwards; a .png must be a PNG
    std::string needs;               // the name of a case run first, in the same folder
    std::string outRegex;            // stdout matches it (std::regex_search), when not empty
    std::string errRegex;            // stderr matches it, when not empty
};

struct CliSuite {
    std::filesystem::path root;               // the cases' folders go below it
    std::map<std::string, std::string> apps;  // app name -> path; an app not built has none
    std::vector<CliCase> cases;
    std::string scenes;  // {S}
};

// The cases whose app (and whose needed case's app) the suite has.
std::vector<CliCase> runnableCases(const CliSuite& suite);

// The program and subcommand of `program`; empty when the suite lacks the app.
std::vector<std::string> appCommand(const CliSuite& suite, const std::string& program);

// Runs the case it needs (which must exit 0), then `c`, and checks every field of `c`.
void checkCliCase(const CliSuite& suite, const CliCase& c);

// For INSTANTIATE_TEST_SUITE_P: the case's name.
std::string caseName(const ::testing::TestParamInfo<CliCase>& info);

// How gtest shows a case in a failure: "prism-bluenoise render --sampler white ...".
void PrintTo(const CliCase& c, std::ostream* os);

}  // namespace prism::test
