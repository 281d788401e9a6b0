// Reflection the oracle cannot see: what `spirv-cross --reflect` does not print (the `used`
// flags, the named values of the JSON) on the fixture made for them (vk_reflection_layouts),
// and --emit-reflection's usage and the spirv target's JSON. The comparison with spirv-cross
// over every Vulkan case of the corpora runs in test_reference_corpus.cpp (reflection_oracle.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "corpus_case.hpp"
#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;
using prism::test::runCommand;
using prism::test::ScratchDir;

const fs::path kCorpusFixtures = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures";

// Runs Prism on the case into `out` (its SPIR-V under spv/, reflection.json); false (with its
// output in `log`) when Prism rejects it.
bool runPrismWithReflection(const prism::test::corpus::Case& c, const fs::path& dir, const fs::path& out,
                            std::string& log) {
    std::vector<std::string> args = {PRISM_SHADERC_EXE};
    const auto caseArgs = prism::test::corpus::prismArguments(c);
    args.insert(args.end(), caseArgs.begin(), caseArgs.end());
    args.insert(args.end(), {"--cache-dir", "none", "--emit-spirv", (out / "spv").string(), "--emit-reflection",
                             (out / "reflection.json").string()});
    const auto r = runCommand(args, {.workDir = dir.string(), .mergeStderr = true});
    log = r.out;
    return r.exitCode == 0;
}

json readReflectionJson(const fs::path& path) {
    return json::parse(prism::test::readFile(path));
}

// What spirv-cross does not print, on the fixture made for it: `used`, and the named values.
TEST(ReflectionOracleFixture, MarksUseAndUnboundedArrays) {
    const fs::path dir = kCorpusFixtures / "reference_corpus/vk_reflection_layouts";
    ScratchDir out("reflection-fixture");
    std::string log;
    ASSERT_TRUE(runPrismWithReflection(prism::test::corpus::loadCase(dir / "case.json"), dir, out.path(), log)) << log;
    const json v = readReflectionJson(out.path() / "reflection.json").at("shaders").at(0).at("variants").at(0);
    std::map<std::string, json> resources, inputs;
    for (const auto& x : v.at("resources")) resources[x.at("name")] = x;
    for (const auto& x : v.at("inputs")) inputs[x.at("name")] = x;
    EXPECT_EQ(resources.at("textures").at("array"), 0) << "textures[] is unbounded (kUnboundedArray)";
    EXPECT_EQ(resources.at("textures").at("used"), true);
    EXPECT_EQ(resources.at("Unused").at("used"), false);
    EXPECT_EQ(resources.at("u_unusedTexture").at("used"), false);
    EXPECT_EQ(resources.at("Materials").at("size"), 32) << "scalar layout: tint at 20, factors[] at 32";
    EXPECT_EQ(resources.at("Materials").at("runtimeStride"), 4);
    EXPECT_EQ(inputs.at("a_unused").at("used"), false);
    EXPECT_EQ(inputs.at("a_unused").at("location"), 3);
    EXPECT_EQ(inputs.at("a_position").at("used"), true);
    const auto& push = v.at("pushConstants");
    ASSERT_EQ(push.size(), 4u) << push.dump();
    EXPECT_EQ(push[1].at("name"), "Push.vertices");
    EXPECT_EQ(push[1].at("offset"), 64);
    EXPECT_EQ(push[1].at("size"), 8);
    EXPECT_EQ(push[1].at("deviceAddress"), true);
}

// --emit-reflection writes the SPIR-V's layout: a usage error where the run makes none, and the
// spirv target's (its loose uniforms in gl_DefaultUniformBlock) where it does.
TEST(ReflectionJson, NeedsSpirvAndCoversTheSpirvTarget) {
    ScratchDir dir("reflection-json");
    dir.write("t.vert",
              "#version 330 core\nin vec3 a_position;\nuniform mat4 u_mvp;\n"
              "void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }\n");
    dir.write("t.frag", "#version 330 core\nuniform vec4 u_color;\nout vec4 o;\nvoid main() { o = u_color; }\n");
    auto run = prism::test::runShaderc("--check --emit-reflection r.json t.vert t.frag", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--emit-reflection r.json writes the SPIR-V's layout, and this run makes none; add the "
                              "spirv target"),
              std::string::npos)
        << run.output;
    run = prism::test::runShaderc("--check --target gl,spirv --emit-reflection r.json t.vert t.frag", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const json r = readReflectionJson(dir.path() / "r.json");
    EXPECT_EQ(r.at("format"), "prism-reflection 1");
    const json& block = r.at("shaders").at(0).at("variants").at(0).at("resources").at(0);
    EXPECT_EQ(block.at("name"), "gl_DefaultUniformBlock");
    std::map<std::string, unsigned> offsets;
    for (const auto& m : block.at("members")) offsets[m.at("name")] = m.at("offset");
    EXPECT_EQ(offsets, (std::map<std::string, unsigned>{{"u_color", 64}, {"u_mvp", 0}})) << block.dump();
}

}  // namespace

namespace {

// An array sized by a constant division that traps at the specialisation constants' defaults
// (INT_MIN / -1, or by zero) is a clear error; SPIRV-Cross would divide and crash the tool.
TEST(ReflectionJson, ATrappingConstantDivisionIsAnErrorNotACrash) {
    ScratchDir dir("reflection-trap");
    for (const std::string divisor : {"-1", "0"}) {
        dir.write("h.comp",
                  "#version 450\nlayout(local_size_x = 1) in;\n"
                  "layout(constant_id = 0) const int A = -2147483647 - 1;\n"
                  "layout(constant_id = 1) const int B = " +
                      divisor +
                      ";\nlayout(std430, binding = 0) buffer Out { uint v[A / B]; } o;\n"
                      "void main() { o.v[0] = 1u; }\n");
        const auto run = prism::test::runShaderc("--client vulkan --check --cache-dir none h.comp", dir.str());
        EXPECT_EQ(run.exitCode, 1) << divisor << "\n" << run.output;
        EXPECT_NE(run.output.find("h.comp: error: cannot reflect the SPIR-V: a constant expression divides by zero or "
                                  "overflows (INT_MIN / -1)"),
                  std::string::npos)
            << run.output;
    }
}

}  // namespace
