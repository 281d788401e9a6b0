// The differential corpus: every folder of fixtures/reference_corpus/ (seed cases) and every
// fixtures/real_corpus/<codebase>/<case>/ (programs of public codebases, real_corpus/SOURCES.md)
// is one test, run by `prism-shaderc --check` and by the reference tool the case names, over
// the same stage files with the same -I folders and -D macros. They must agree on accept or
// reject and, when both reject, Prism's first error must name the reference's first error's
// file and line. A case may instead expect a known difference ("expect"), which is then
// what it checks: the claims of docs/shaderc.md's "Coming from glslc" are such cases.
// Where both accept, Prism's outputs are checked too: each SPIR-V module of a Vulkan case by
// spirv-val (with the layout options its source's extensions ask for), and each es300 text by
// `glslangValidator -l` and for samplers left at ES's lowp default.
//
// case.json (a folder is a case; tests/README.md says how to add one):
//   "checks":       one line, what the case shows (required)
//   "client":       "opengl" | "vulkan" (vulkan adds --client vulkan to Prism's arguments)
//   "stages":       stage files, relative to the case folder (required)
//   "include_dirs": -I folders for both tools; "defines": NAME[=VALUE] for both tools
//   "prism_args":   more prism-shaderc arguments
//   "program":      a name: the stages go to Prism as `--program NAME=STAGE,...` (stages of other base names)
//   "prism_target": "es300": Prism runs with --target es300 (desktop GL source; the reference checks it as is)
//   "reference":    "glslangValidator -l" | "glslangValidator -V" | "glslc --target-env=vulkan1.N" (N 0..3;
//                   a Vulkan case hands Prism the same --target-env)
//   "expect":       {"prism": "accept"|"reject", "reference": "accept"|"reject"} (default: agree)
//   "prism_says":   text Prism's output must contain (a warning the case is about)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "corpus_case.hpp"
#include "corpus_output_checks.hpp"
#include "reflection_oracle.hpp"
#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using prism::test::runCommand;
using prism::test::corpus::Case;
using prism::test::corpus::loadCase;

const fs::path kCorpus = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/reference_corpus";
const fs::path kRealCorpus = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/real_corpus";

// The sorted subfolders of `dir`, less `except`.
std::vector<std::string> subfolders(const fs::path& dir, const std::string& except = "") {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.is_directory() && entry.path().filename() != except)
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Every folder of the seed corpus; one without case.json fails its test rather than being skipped.
std::vector<std::string> caseNames() {
    return subfolders(kCorpus);
}

// Every <codebase>/<case> of the real corpus: each folder of a codebase but its copied `source/`.
std::vector<std::string> realCaseNames() {
    std::vector<std::string> names;
    for (const auto& codebase : subfolders(kRealCorpus))
        for (const auto& name : subfolders(kRealCorpus / codebase, "source")) names.push_back(codebase + "/" + name);
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

// Prism over the case; its SPIR-V and reflection (Vulkan) or es300 text go to `emitted`.
Outcome runPrism(const Case& c, const fs::path& dir, const fs::path& emitted) {
    std::vector<std::string> args = {PRISM_SHADERC_EXE};
    const auto caseArgs = prism::test::corpus::prismArguments(c);
    args.insert(args.end(), caseArgs.begin(), caseArgs.end());
    if (c.client == "vulkan")
        args.insert(args.end(),
                    {"--emit-spirv", emitted.string(), "--emit-reflection", (emitted / "reflection.json").string()});
    if (c.prismTarget == "es300") args.insert(args.end(), {"--emit-glsl", emitted.string()});
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
        std::vector<std::string> args = {"glslc", "--target-env=" + c.targetEnv, "-c", "-o", "/dev/null"};
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

// Each SPIR-V module Prism wrote, through spirv-val in the case's Vulkan environment with the layout options
// its source's extensions imply. Returns one report line per rejected module.
std::vector<std::string> spirvValRejections(const Case& c, const fs::path& emitted) {
    std::vector<std::string> rejected;
    for (const auto& entry : fs::directory_iterator(emitted)) {
        if (entry.path().extension() != ".spv") continue;
        std::vector<std::string> args = {"spirv-val", "--target-env", c.targetEnv.empty() ? "vulkan1.2" : c.targetEnv};
        for (const auto& option : prism::test::spirvValLayoutOptions(prism::test::spirvSourceExtensions(entry.path())))
            args.push_back(option);
        args.push_back(entry.path().string());
        const auto r = runCommand(args, {.workDir = {}, .mergeStderr = true});
        if (r.exitCode != 0) rejected.push_back(entry.path().filename().string() + ": " + r.out);
    }
    return rejected;
}

// The es300 texts Prism wrote, linked by `glslangValidator -l` as GLSL ES 3.00, and anything its tree computes
// or declares at lowp. Returns one report line per problem.
std::vector<std::string> es300Problems(const fs::path& emitted) {
    std::vector<std::string> stages;
    for (const auto& entry : fs::directory_iterator(emitted))
        if (entry.path().filename().string().find(".es300.") != std::string::npos)
            stages.push_back(entry.path().string());
    if (stages.empty()) return {"no es300 stage was written to " + emitted.string()};
    std::sort(stages.begin(), stages.end());
    std::vector<std::string> args = {"glslangValidator", "-l", "-i"};
    args.insert(args.end(), stages.begin(), stages.end());
    const auto r = runCommand(args, {.workDir = {}, .mergeStderr = true});
    if (r.exitCode != 0) return {"glslangValidator -l rejects the es300 text:\n" + r.out};
    if (const auto lowp = prism::test::lowpLines(r.out); !lowp.empty())
        return {"the es300 text computes or declares at GLSL ES 3.00's default lowp:\n" + lowp};
    return {};
}

// The outputs of a program both tools accept: SPIR-V through spirv-val, es300 text through glslang and
// the precision rule.
void checkPrismOutputs(const Case& c, const fs::path& emitted, const std::string& report) {
    std::vector<std::string> problems;
    if (c.client == "vulkan") {
        problems = spirvValRejections(c, emitted);
        for (auto& p : prism::test::reflectionDisagreements(emitted / "reflection.json", emitted))
            problems.push_back(std::move(p));
    }
    if (c.prismTarget == "es300") problems = es300Problems(emitted);
    for (const auto& problem : problems) ADD_FAILURE() << problem << "\n" << report;
}

// One case: the folder `dir`, named `name` in the reports.
void checkCase(const fs::path& dir, const std::string& name) {
    Case c;
    try {
        c = loadCase(dir / "case.json");
    } catch (const std::exception& e) {
        FAIL() << (dir / "case.json").string() << ": " << e.what();
    }
    const prism::test::ScratchDir emitted("corpus-" + std::to_string(std::hash<std::string>{}(name)));
    const Outcome prism = runPrism(c, dir, emitted.path());
    const Outcome reference = runReference(c, dir);
    const std::string report = "case " + name + " (" + c.checks + ")\n--- prism-shaderc " + verdict(prism.accepted) +
                               ":\n" + prism.output + "--- " + c.reference + " " + verdict(reference.accepted) + ":\n" +
                               reference.output;
    if (c.prismAccepts || c.referenceAccepts) {
        EXPECT_EQ(prism.accepted, c.prismAccepts.value_or(reference.accepted)) << "expected difference\n" << report;
        EXPECT_EQ(reference.accepted, c.referenceAccepts.value_or(prism.accepted)) << "expected difference\n" << report;
    } else {
        EXPECT_EQ(prism.accepted, reference.accepted) << "accept/reject disagree\n" << report;
    }
    if (!c.prismSays.empty()) {
        EXPECT_NE(prism.output.find(c.prismSays), std::string::npos) << report;
    }
    if (prism.accepted && reference.accepted) checkPrismOutputs(c, emitted.path(), report);
    if (prism.accepted || reference.accepted || !reference.firstError) return;
    ASSERT_TRUE(prism.firstError) << "Prism's rejection names no file:line:col\n" << report;
    EXPECT_EQ(prism.firstError->first, reference.firstError->first) << "first error's file\n" << report;
    EXPECT_EQ(prism.firstError->second, reference.firstError->second) << "first error's line\n" << report;
}

class ReferenceCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceCorpus, PrismAgreesWithTheReference) {
    checkCase(kCorpus / GetParam(), GetParam());
}

class ReferenceCorpusRealCode : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceCorpusRealCode, PrismAgreesWithTheReference) {
    checkCase(kRealCorpus / GetParam(), GetParam());
}

// gtest names allow letters, digits and '_': other characters of a folder name become '_'.
std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, ReferenceCorpus, ::testing::ValuesIn(caseNames()), testName);
INSTANTIATE_TEST_SUITE_P(Programs, ReferenceCorpusRealCode, ::testing::ValuesIn(realCaseNames()), testName);

// The corpus is found at run time: an empty or missing folder would pass nothing at all.
TEST(ReferenceCorpusFolder, HoldsTheSeedCases) {
    EXPECT_GE(caseNames().size(), 12u) << kCorpus;
}

// The real corpus keeps what issue 36 asked of it: six Vulkan codebases or more and one desktop-GL one, each
// with its licence beside the copied files, listed in SOURCES.md.
TEST(ReferenceCorpusFolder, HoldsTheRealCodebases) {
    const auto codebases = subfolders(kRealCorpus);
    EXPECT_GE(codebases.size(), 7u) << kRealCorpus;
    EXPECT_GE(realCaseNames().size(), 60u) << kRealCorpus;
    const std::string manifest = prism::test::readFile(kRealCorpus / "SOURCES.md");
    for (const auto& codebase : codebases)
        EXPECT_NE(manifest.find("`" + codebase + "`"), std::string::npos) << codebase << " is not in SOURCES.md";
}

// The precision rule of the es300 cases: the precision lines es300 wrote before issue 36 leave sampler2D and
// samplerCube at lowp in glslang's tree, and `precision highp sampler2D; precision highp samplerCube;` cover them.
TEST(ReferenceCorpusChecks, SamplersLeftAtLowpNeedAPrecisionForTheirType) {
    const prism::test::ScratchDir dir("corpus-lowp");
    const std::string body =
        "uniform sampler2D gPosition;\nstruct M { sampler2D diffuse; };\nuniform M m;\n"
        "uniform samplerCube sky;\nin vec2 uv;\nout vec4 o;\n"
        "void main() { o = texture(gPosition, uv) + texture(m.diffuse, uv) + "
        "texture(sky, vec3(uv, 1.0)); }\n";
    const std::string before = "#version 300 es\nprecision highp float;\nprecision highp sampler3D;\n";
    const auto lowpOf = [&](const std::string& text) {
        dir.write("s.frag", text);
        const auto r = runCommand({"glslangValidator", "-i", (dir.path() / "s.frag").string()},
                                  {.workDir = {}, .mergeStderr = true});
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return prism::test::lowpLines(r.out);
    };
    const auto left = lowpOf(before + body);
    for (const std::string name : {"'gPosition' ( uniform lowp sampler2D)", "'sky' ( uniform lowp samplerCube)"})
        EXPECT_NE(left.find(name), std::string::npos) << name << " in\n" << left;
    EXPECT_EQ(lowpOf(before + "precision highp sampler2D;\nprecision highp samplerCube;\n" + body), "");
}

// spirv-val's layout options come from the module: glslc's SPIR-V of a scalar-layout stage of the corpus names
// GL_EXT_scalar_block_layout, fails spirv-val without --scalar-block-layout and passes with it.
// The C++ structs of every block of every Vulkan program of both corpora that Prism accepts
// (the corpus tests judge which): each program's header written, then all of them compiled
// together, so each struct's static_asserts on sizeof and offsetof hold against the compiler.
TEST(ReferenceCorpusChecks, BlockStructsOfEveryAcceptedVulkanProgramCompile) {
    const prism::test::ScratchDir out("corpus-structs");
    std::string includes, refused;
    int headers = 0;
    const auto writeHeader = [&](const fs::path& dir, const std::string& name) {
        const Case c = loadCase(dir / "case.json");
        if (c.client != "vulkan") return;
        std::vector<std::string> args = {PRISM_SHADERC_EXE};
        for (const auto& a : prism::test::corpus::prismArguments(c))
            if (a != "--check") args.push_back(a);
        const std::string header = (out.path() / ("c" + std::to_string(headers) + ".hpp")).string();
        args.insert(args.end(),
                    {"--cache-dir", "none", "-o", header, "--namespace", "corpus::c" + std::to_string(headers)});
        const auto r = runCommand(args, {.workDir = dir.string(), .mergeStderr = true});
        if (r.exitCode != 0) {
            refused += name + " ";
            return;
        }
        includes += "#include \"" + header + "\"\n";
        ++headers;
    };
    for (const auto& name : caseNames()) writeHeader(kCorpus / name, name);
    for (const auto& name : realCaseNames()) writeHeader(kRealCorpus / name, name);
    EXPECT_GE(headers, 90) << "Vulkan programs Prism refused: " << refused;
    const auto all = out.path() / "all_blocks.cpp";
    prism::test::writeFile(all, includes);
    const auto cc = runCommand(
        {"c++", "-std=c++20", "-fsyntax-only", "-I", PRISM_SOURCE_DIR "/foundation/catalog/include", all.string()},
        {.workDir = {}, .mergeStderr = true});
    ASSERT_EQ(cc.exitCode, 0) << cc.out;
    int asserts = 0;
    for (int i = 0; i < headers; ++i) {
        const auto h = prism::test::readFile(out.path() / ("c" + std::to_string(i) + ".hpp"));
        for (auto at = h.find("static_assert(offsetof"); at != std::string::npos;
             at = h.find("static_assert(offsetof", at + 1))
            ++asserts;
    }
    EXPECT_GE(asserts, 500) << "the corpus's blocks have fewer member checks than expected";
}

TEST(ReferenceCorpusChecks, ScalarLayoutStageGetsSpirvValsScalarOption) {
    const fs::path dir = kRealCorpus / "nvpro_vk_mini_path_tracer/source/vk_mini_path_tracer";
    const prism::test::ScratchDir out("corpus-scalar");
    const fs::path spv = out.path() / "raytrace.spv";
    ASSERT_EQ(runCommand({"glslc", "--target-env=vulkan1.2", "-I", dir.string(), "-c", "-o", spv.string(),
                          (dir / "shaders/raytrace.comp").string()},
                         {.workDir = {}, .mergeStderr = true})
                  .exitCode,
              0);
    const auto options = prism::test::spirvValLayoutOptions(prism::test::spirvSourceExtensions(spv));
    EXPECT_EQ(options, std::vector<std::string>{"--scalar-block-layout"});
    const auto plain =
        runCommand({"spirv-val", "--target-env", "vulkan1.2", spv.string()}, {.workDir = {}, .mergeStderr = true});
    EXPECT_NE(plain.exitCode, 0) << "without the option spirv-val should reject the scalar layout";
    const auto scalar = runCommand({"spirv-val", "--target-env", "vulkan1.2", "--scalar-block-layout", spv.string()},
                                   {.workDir = {}, .mergeStderr = true});
    EXPECT_EQ(scalar.exitCode, 0) << scalar.out;
}

}  // namespace
