// The differential corpus: every folder of fixtures/reference_corpus/ with a case.json is
// one test, run by `prism-shaderc --check` and by the reference tool the case names, over
// the same stage files with the same -I folders and -D macros. They must agree on accept or
// reject and, when both reject, Prism's first error must name the reference's first error's
// file and line. A case may instead expect a known difference ("expect"), which is then
// what it checks: the claims of docs/shaderc.md's "Coming from glslc" are such cases.
//
// case.json (a folder is a case; tests/README.md says how to add one):
//   "checks":       one line, what the case shows (required)
//   "client":       "opengl" | "vulkan" (vulkan adds --client vulkan to Prism's arguments)
//   "stages":       stage files, relative to the case folder (required)
//   "include_dirs": -I folders for both tools; "defines": NAME[=VALUE] for both tools
//   "prism_args":   more prism-shaderc arguments
//   "reference":    "glslangValidator -l" | "glslangValidator -V" | "glslc --target-env=vulkan1.2"
//   "expect":       {"prism": "accept"|"reject", "reference": "accept"|"reject"} (default: agree)
//   "prism_says":   text Prism's output must contain (a warning the case is about)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "corpus_case.hpp"
#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using prism::test::runCommand;
using prism::test::corpus::Case;
using prism::test::corpus::loadCase;

const fs::path kCorpus = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/reference_corpus";

// Every folder of the corpus, sorted; one without case.json fails its test rather than
// being skipped.
std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(kCorpus, ec))
        if (entry.is_directory()) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

struct Outcome {
    bool accepted = false;
    std::string output;
    std::optional<std::pair<std::string, int>> firstError;  // file (normalised), line
};

// The first `path:line` error in `output` matched by `pattern` (groups 1 and 2).
std::optional<std::pair<std::string, int>> firstError(const std::string& output, const std::regex& pattern) {
    std::smatch m;
    if (!std::regex_search(output, m, pattern)) return std::nullopt;
    return std::pair{fs::path(m[1].str()).lexically_normal().generic_string(), std::stoi(m[2].str())};
}

Outcome runPrism(const Case& c, const fs::path& dir) {
    std::vector<std::string> args = {PRISM_SHADERC_EXE, "--check"};
    if (c.client == "vulkan") args.insert(args.end(), {"--client", "vulkan"});
    for (const auto& d : c.includeDirs) args.insert(args.end(), {"-I", d});
    for (const auto& d : c.defines) args.insert(args.end(), {"-D", d});
    args.insert(args.end(), c.prismArgs.begin(), c.prismArgs.end());
    args.insert(args.end(), c.stages.begin(), c.stages.end());
    const auto r = runCommand(args, {.workDir = dir.string(), .mergeStderr = true});
    static const std::regex error(R"((?:^|\n)([^\n:]+):(\d+):\d+: error: )");
    return {r.exitCode == 0, r.out, firstError(r.out, error)};
}

// The reference over the same files. glslc compiles one file per run (it does not link),
// so each stage is a run and the first failing one gives the error.
Outcome runReference(const Case& c, const fs::path& dir) {
    static const std::regex glslangError(R"((?:^|\n)ERROR: ([^\n:]+):(\d+): )");
    static const std::regex glslcError(R"((?:^|\n)([^\n:]+):(\d+): error: )");
    const auto run = [&](std::vector<std::string> args) {
        const auto r = runCommand(args, {.workDir = dir.string(), .mergeStderr = true});
        return std::pair{r.exitCode == 0, r.out};
    };
    Outcome outcome{true, "", std::nullopt};
    if (c.reference.starts_with("glslangValidator")) {
        std::vector<std::string> args = {"glslangValidator", "-l"};  // -l: links the stages
        if (c.reference.ends_with("-V")) args.insert(args.end(), {"-V", "-o", "/dev/null"});
        for (const auto& d : c.includeDirs) args.push_back("-I" + d);
        for (const auto& d : c.defines) args.push_back("-D" + d);
        args.insert(args.end(), c.stages.begin(), c.stages.end());
        std::tie(outcome.accepted, outcome.output) = run(args);
        outcome.firstError = firstError(outcome.output, glslangError);
        return outcome;
    }
    for (const auto& stage : c.stages) {
        std::vector<std::string> args = {"glslc", "--target-env=vulkan1.2", "-c", "-o", "/dev/null"};
        for (const auto& d : c.includeDirs) args.insert(args.end(), {"-I", d});
        for (const auto& d : c.defines) args.push_back("-D" + d);
        args.push_back(stage);
        auto [ok, out] = run(args);
        outcome.output += out;
        if (!ok && outcome.accepted) outcome.firstError = firstError(out, glslcError);
        outcome.accepted = outcome.accepted && ok;
    }
    return outcome;
}

std::string verdict(bool accepted) {
    return accepted ? "accepts" : "rejects";
}

class ReferenceCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceCorpus, PrismAgreesWithTheReference) {
    const fs::path dir = kCorpus / GetParam();
    Case c;
    try {
        c = loadCase(dir / "case.json");
    } catch (const std::exception& e) {
        FAIL() << (dir / "case.json").string() << ": " << e.what();
    }
    const Outcome prism = runPrism(c, dir);
    const Outcome reference = runReference(c, dir);
    const std::string report = "case " + GetParam() + " (" + c.checks + ")\n--- prism-shaderc " +
                               verdict(prism.accepted) + ":\n" + prism.output + "--- " + c.reference + " " +
                               verdict(reference.accepted) + ":\n" + reference.output;
    if (c.prismAccepts || c.referenceAccepts) {
        EXPECT_EQ(prism.accepted, c.prismAccepts.value_or(reference.accepted)) << "expected difference\n" << report;
        EXPECT_EQ(reference.accepted, c.referenceAccepts.value_or(prism.accepted)) << "expected difference\n" << report;
    } else {
        EXPECT_EQ(prism.accepted, reference.accepted) << "accept/reject disagree\n" << report;
    }
    if (!c.prismSays.empty()) {
        EXPECT_NE(prism.output.find(c.prismSays), std::string::npos) << report;
    }
    if (prism.accepted || reference.accepted || !reference.firstError) return;
    ASSERT_TRUE(prism.firstError) << "Prism's rejection names no file:line:col\n" << report;
    EXPECT_EQ(prism.firstError->first, reference.firstError->first) << "first error's file\n" << report;
    EXPECT_EQ(prism.firstError->second, reference.firstError->second) << "first error's line\n" << report;
}

// gtest names allow letters, digits and '_': other characters of a folder name become '_'.
std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, ReferenceCorpus, ::testing::ValuesIn(caseNames()), testName);

// The corpus is found at run time: an empty or missing folder would pass nothing at all.
TEST(ReferenceCorpusFolder, HoldsTheSeedCases) {
    EXPECT_GE(caseNames().size(), 12u) << kCorpus;
}

}  // namespace
