// prism-shaderc as a program: golden text tests of generated headers (glslang's
// baseResults idea; set PRISM_UPDATE_BASELINES=1 to rewrite them), determinism,
// change-only writes, nothing written on error, driver-safe --emit-glsl output,
// depfile escaping, exit codes, and one report per module error.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <thread>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

const std::string kSource = PRISM_SOURCE_DIR;
const std::string kFixture = kSource + "/tests/shaderc/fixtures/variants";
const std::string kBaseResults = kSource + "/tests/shaderc/baseResults";

// The project catalogue with the light counts pinned (2 directional, 1 point), so the
// baseline stays small: the other light variants differ only in their #defines.
std::string catalogueArgs() {
    return "--base-dir " + kSource + " --variant '*:DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1' -I " + kSource +
           "/modules --contract " + kSource + "/modules/contract.json " + kSource + "/shader_sources";
}

std::string fixtureArgs() {
    return "--base-dir " + kSource + " -I " + kFixture + "/modules --contract " + kFixture + "/contract.json " +
           kFixture + "/shaders";
}

bool updateMode() {
    const char* v = std::getenv("PRISM_UPDATE_BASELINES");
    return v && std::string(v) == "1";
}

void expectMatchesBaseline(const std::string& actual, const std::string& name) {
    const fs::path baseline = fs::path(kBaseResults) / name;
    if (updateMode()) {
        prism::test::writeFile(baseline, actual);
        GTEST_SKIP() << "rewrote " << baseline << " (PRISM_UPDATE_BASELINES=1); this run checked nothing";
    }
    ASSERT_TRUE(fs::exists(baseline)) << baseline << " is missing; run with PRISM_UPDATE_BASELINES=1 to create it";
    EXPECT_TRUE(actual == readFile(baseline))
        << "generated header differs from " << baseline
        << "; inspect the difference and, if intended, rerun with PRISM_UPDATE_BASELINES=1";
}

}  // namespace

TEST(GoldenHeader, ProjectCatalogue) {
    ScratchDir dir("golden-catalogue");
    auto run = runShaderc("-o catalogue.hpp " + catalogueArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    expectMatchesBaseline(readFile(dir.path() / "catalogue.hpp"), "catalogue.hpp");
}

TEST(GoldenHeader, VariantsGeometryAndCompute) {
    ScratchDir dir("golden-variants");
    auto run = runShaderc("-o variants.hpp --namespace fixture::shaders " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto header = readFile(dir.path() / "variants.hpp");
    // The FOG=0 variants must not contain the fog module: it is included under #if FOG.
    EXPECT_NE(header.find("{\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_NE(header.find("prism::catalog::Stage::Geometry"), std::string::npos);
    EXPECT_NE(header.find("prism::catalog::Stage::Compute"), std::string::npos);
    expectMatchesBaseline(header, "variants.hpp");
}

TEST(ToolDeterminism, TwoRunsAndJobCountsGiveIdenticalBytes) {
    ScratchDir dir("determinism");
    fs::create_directories(dir.path() / "a");
    fs::create_directories(dir.path() / "b");
    ASSERT_EQ(runShaderc("-j 1 -o out.hpp " + fixtureArgs(), (dir.path() / "a").string()).exitCode, 0);
    ASSERT_EQ(runShaderc("-j 4 -o out.hpp " + fixtureArgs(), (dir.path() / "b").string()).exitCode, 0);
    const auto one = readFile(dir.path() / "a/out.hpp");
    EXPECT_FALSE(one.empty());
    EXPECT_EQ(one, readFile(dir.path() / "b/out.hpp"));
    fs::remove(dir.path() / "a/out.hpp");
    ASSERT_EQ(runShaderc("-j 2 -o out.hpp " + fixtureArgs(), (dir.path() / "a").string()).exitCode, 0);
    EXPECT_EQ(readFile(dir.path() / "a/out.hpp"), one);
}

TEST(ToolOutputs, UnchangedHeaderKeepsItsTimestampAndErrorsWriteNothing) {
    ScratchDir dir("mtime");
    fs::copy(kFixture, dir.path() / "fx", fs::copy_options::recursive);
    const std::string args = "-o out.hpp --base-dir . -I fx/modules --contract fx/contract.json fx/shaders";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto header = dir.path() / "out.hpp";
    const auto firstTime = fs::last_write_time(header);
    const auto firstText = readFile(header);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(fs::last_write_time(header), firstTime);

    dir.write("fx/modules/tint.glsl",
              "// Provides: a broken tint.\nuniform vec3 u_tint;\nvec3 tint(vec3 c) { return c * missing; }\n");
    auto broken = runShaderc(args, dir.str());
    EXPECT_EQ(broken.exitCode, 1);
    EXPECT_NE(broken.output.find("fx/modules/tint.glsl:3:"), std::string::npos) << broken.output;
    EXPECT_EQ(readFile(header), firstText);
    EXPECT_EQ(fs::last_write_time(header), firstTime);
    for (const auto& e : fs::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << "left a temporary file " << e.path();
}

// The no-op is decided on the sources the header records (source_fingerprint.hpp):
// any change to a file read, or a new module in an -I folder, rebuilds.
TEST(ToolOutputs, NoOpChecksTheRecordedSources) {
    ScratchDir dir("noop");
    fs::copy(kFixture, dir.path() / "fx", fs::copy_options::recursive);
    const std::string args =
        "-o out.hpp --depfile out.d --base-dir . -I fx/modules --contract fx/contract.json fx/shaders";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto header = dir.path() / "out.hpp";
    const std::string first = readFile(header);
    EXPECT_NE(first.find("// ---- sources read (prism-shaderc's no-op check): "), std::string::npos);
    EXPECT_NE(first.find("\n//   fx/modules/fog.glsl\n"), std::string::npos);
    fs::remove(dir.path() / "out.d");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(readFile(header), first);
    EXPECT_NE(readFile(dir.path() / "out.d").find("fx/modules/fog.glsl"), std::string::npos)
        << "the no-op writes the depfile";

    dir.write("fx/modules/fog.glsl", readFile(dir.path() / "fx/modules/fog.glsl") + "// one more comment line\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const std::string edited = readFile(header);
    EXPECT_NE(edited.find("// one more comment line"), std::string::npos);

    dir.write("fx/modules/extra.glsl", "// Provides: a module nobody includes yet.\nfloat extra() { return 1.0; }\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_NE(readFile(header).find("    extra = "), std::string::npos);
}

TEST(ToolOutputs, EmittedGlslIsDriverSafe) {
    ScratchDir dir("emit");
    auto run = runShaderc("--emit-glsl glsl " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    int files = 0;
    const std::regex lineDirective(R"(^#line \d+ \d+$)");
    for (const auto& e : fs::directory_iterator(dir.path() / "glsl")) {
        ++files;
        auto text = readFile(e.path());
        EXPECT_EQ(text.rfind("#version ", 0), 0u) << e.path();
        EXPECT_EQ(text.find("GL_GOOGLE"), std::string::npos) << e.path();
        EXPECT_EQ(text.find("GL_ARB_shading_language_include"), std::string::npos) << e.path();
        EXPECT_EQ(text.find("#pragma prism"), std::string::npos) << e.path();
        std::istringstream lines(text);
        for (std::string l; std::getline(lines, l);)
            if (l.rfind("#line", 0) == 0) {
                EXPECT_TRUE(std::regex_match(l, lineDirective)) << l;
            }
    }
    EXPECT_EQ(files, 4 * 2 + 3 + 1);  // tinted: 4 variants x 2 stages; sprites: 3 stages; step: 1
}

TEST(ToolOutputs, DepfileEscapesPathsWithSpaces) {
    ScratchDir dir("dep");
    fs::copy(kFixture, dir.path() / "my fx$#", fs::copy_options::recursive);
    const std::string fx = "'" + (dir.path() / "my fx$#").string() + "'";
    auto run = runShaderc(
        "-o out.hpp --depfile out.d -I " + fx + "/modules --contract " + fx + "/contract.json " + fx + "/shaders",
        dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto dep = readFile(dir.path() / "out.d");
    EXPECT_EQ(dep.rfind("out.hpp:", 0), 0u) << dep;
    EXPECT_NE(dep.find("my\\ fx$$\\#/modules/tint.glsl"), std::string::npos) << dep;
    EXPECT_NE(dep.find("my\\ fx$$\\#/shaders/step.comp"), std::string::npos) << dep;
    EXPECT_NE(dep.find("contract.json"), std::string::npos) << dep;
}

TEST(ToolExitCodes, UsageAndMissingInputs) {
    EXPECT_EQ(runShaderc("--no-such-option x.vert").exitCode, 2);
    EXPECT_EQ(runShaderc("--check").exitCode, 2);
    EXPECT_EQ(runShaderc("--version").exitCode, 0);
    auto missing = runShaderc("--check /nonexistent/a.vert");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("/nonexistent/a.vert: error: no such file"), std::string::npos);
}

TEST(ToolDiagnostics, ModuleErrorReportedOnceForManyShadersWithChain) {
    ScratchDir dir("once");
    dir.write("m/bad.glsl",
              "// Provides: a broken helper.\nvec3 helper(vec3 x) {\n    return x * undefinedThing;\n}\n");
    for (std::string s : {"a", "b", "c"}) {
        dir.write("s/" + s + ".vert",
                  "#version 330 core\n#include <bad.glsl>\nin vec3 a_position;\n"
                  "void main() { gl_Position = vec4(helper(a_position), 1.0); }\n");
        dir.write("s/" + s + ".frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n");
    }
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    const std::string line =
        "m/bad.glsl:3:16: error: 'undefinedThing': undeclared identifier\n  included from s/a.vert:2\n";
    auto first = run.output.find(line);
    ASSERT_NE(first, std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("m/bad.glsl:3:16", first + 1), std::string::npos) << run.output;
}

TEST(ToolDiagnostics, IncludeCycleFailsPromptlyWithTheChain) {
    ScratchDir dir("cycle");
    dir.write("m/a.glsl", "// Provides: a.\n#include \"b.glsl\"\n");
    dir.write("m/b.glsl", "// Provides: b.\n#include \"a.glsl\"\n");
    dir.write("s/p.vert", "#version 330 core\n#include <a.glsl>\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/p.frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n");
    auto start = std::chrono::steady_clock::now();
    auto run = runShaderc("--check -I m s", dir.str());
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("m/b.glsl:2:10: error: include cycle: m/a.glsl -> m/b.glsl -> m/a.glsl"),
              std::string::npos)
        << run.output;
}

TEST(ToolDiagnostics, MsvcFormat) {
    ScratchDir dir("msvc");
    dir.write("s/p.vert", "#version 330 core\nvoid main() { gl_Position = nope; }\n");
    dir.write("s/p.frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n");
    auto run = runShaderc("--check --errfmt msvc s", dir.str());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("s/p.vert(2,29): error: 'nope': undeclared identifier"), std::string::npos) << run.output;
}

TEST(ToolVariants, FilterEmitsOnlyTheAskedVariants) {
    ScratchDir dir("filter");
    auto run = runShaderc("--variant tinted:FOG=1,LIGHTS=2 -o f.hpp " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto header = readFile(dir.path() / "f.hpp");
    EXPECT_NE(header.find("\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_EQ(header.find("\"FOG=0,LIGHTS=1\""), std::string::npos);
    EXPECT_EQ(runShaderc("--check --variant tinted:FOG=7 " + fixtureArgs(), dir.str()).exitCode, 1);
}

TEST(ToolVariants, WildcardFilterAndItsTypoCheck) {
    ScratchDir dir("wildcard");
    auto run = runShaderc("--variant '*:LIGHTS=2' -o w.hpp " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto header = readFile(dir.path() / "w.hpp");
    EXPECT_NE(header.find("\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_EQ(header.find("LIGHTS=1\""), std::string::npos);
    auto typo = runShaderc("--check --variant '*:LIGTHS=2' " + fixtureArgs(), dir.str());
    EXPECT_EQ(typo.exitCode, 1);
    EXPECT_NE(typo.output.find("no shader declares a variant 'LIGTHS'"), std::string::npos) << typo.output;
}
