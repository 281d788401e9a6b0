// prism-shaderc as a program: golden text tests of generated headers and data files
// (glslang's baseResults idea; set PRISM_UPDATE_BASELINES=1 to rewrite them), determinism,
// change-only writes, nothing written on error, driver-safe --emit-glsl output,
// depfile escaping, exit codes, and one report per module error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
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
        << "generated text differs from " << baseline
        << "; inspect the difference and, if intended, rerun with PRISM_UPDATE_BASELINES=1";
}

}  // namespace

TEST(GoldenHeader, ProjectCatalogue) {
    ScratchDir dir("golden-catalogue");
    auto run = runShaderc("-o catalogue.hpp --namespace prism::shaders " + catalogueArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto header = readFile(dir.path() / "catalogue.hpp");
    const auto data = readFile(dir.path() / "catalogue.cpp");
    // The project's modules and shaders are copied into the data verbatim, so they
    // cite no other engine either (docs/references.md says which thesis each follows).
    std::string lower = header + data;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(lower.find("fudge"), std::string::npos) << "the project catalogue mentions FUDGE";
    expectMatchesBaseline(header, "catalogue.hpp");
    expectMatchesBaseline(data, "catalogue.cpp.txt");
}

TEST(GoldenHeader, VariantsGeometryAndCompute) {
    ScratchDir dir("golden-variants");
    auto run = runShaderc("-o variants.hpp --namespace fixture::shaders " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto header = readFile(dir.path() / "variants.hpp");
    const auto data = readFile(dir.path() / "variants.cpp");
    // The FOG=0 variants must not contain the fog module: it is included under #if FOG.
    EXPECT_NE(data.find("{\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_NE(data.find("prism::catalog::Stage::Geometry"), std::string::npos);
    EXPECT_NE(data.find("prism::catalog::Stage::Compute"), std::string::npos);
    expectMatchesBaseline(header, "variants.hpp");
    expectMatchesBaseline(data, "variants.cpp.txt");
}

// Without --namespace the namespace is the header's name, as prism_add_shaders() names a
// catalogue after its target (toon_shaders.hpp and toon_shaders): never Prism's prism::shaders.
TEST(ToolOutputs, NamespaceDefaultsToTheHeadersName) {
    ScratchDir dir("default-namespace");
    auto run = runShaderc("-o gen/toon-shaders.hpp " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto header = readFile(dir.path() / "gen" / "toon-shaders.hpp");
    EXPECT_NE(header.find("\nnamespace toon_shaders {\n"), std::string::npos) << header.substr(0, 1200);
    EXPECT_EQ(header.find("prism::shaders"), std::string::npos);
    EXPECT_NE(readFile(dir.path() / "gen" / "toon-shaders.cpp").find("\nnamespace toon_shaders {\n"),
              std::string::npos);

    run = runShaderc("-o gen/toon-shaders.hpp --namespace lit::toon " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(readFile(dir.path() / "gen" / "toon-shaders.hpp").find("\nnamespace lit::toon {\n"), std::string::npos);
}

// The header's own text (banner and the comments the tool writes) is Prism's: it names
// prism-shaderc, says not to edit, and mentions no other engine. The fixture's sources
// mention none either, so any such word would come from the tool.
TEST(GoldenHeader, BannerIsPrismsOwn) {
    ScratchDir dir("banner");
    auto run = runShaderc("-o banner.hpp --namespace fixture::shaders " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto header = readFile(dir.path() / "banner.hpp");
    const auto data = readFile(dir.path() / "banner.cpp");
    for (const auto& text : {header, data}) {
        EXPECT_EQ(text.rfind("// Generated by prism-shaderc ", 0), 0u) << text.substr(0, 200);
        EXPECT_NE(text.find("Do not edit"), std::string::npos);
    }
    std::string lower = header + data;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(lower.find("fudge"), std::string::npos) << "the generated header mentions FUDGE";
}

TEST(ToolDeterminism, TwoRunsAndJobCountsGiveIdenticalBytes) {
    ScratchDir dir("determinism");
    fs::create_directories(dir.path() / "a");
    fs::create_directories(dir.path() / "b");
    ASSERT_EQ(runShaderc("-j 1 -o out.hpp " + fixtureArgs(), (dir.path() / "a").string()).exitCode, 0);
    ASSERT_EQ(runShaderc("-j 4 -o out.hpp " + fixtureArgs(), (dir.path() / "b").string()).exitCode, 0);
    const auto one = readFile(dir.path() / "a/out.hpp") + readFile(dir.path() / "a/out.cpp");
    EXPECT_FALSE(one.empty());
    EXPECT_EQ(one, readFile(dir.path() / "b/out.hpp") + readFile(dir.path() / "b/out.cpp"));
    fs::remove(dir.path() / "a/out.hpp");
    fs::remove(dir.path() / "a/out.cpp");
    ASSERT_EQ(runShaderc("-j 2 -o out.hpp " + fixtureArgs(), (dir.path() / "a").string()).exitCode, 0);
    EXPECT_EQ(readFile(dir.path() / "a/out.hpp") + readFile(dir.path() / "a/out.cpp"), one);
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

// The no-op is decided on the sources the data file records (source_fingerprint.hpp):
// any change to a file read, or a new module in an -I folder, rebuilds.
TEST(ToolOutputs, NoOpChecksTheRecordedSources) {
    ScratchDir dir("noop");
    fs::copy(kFixture, dir.path() / "fx", fs::copy_options::recursive);
    const std::string args =
        "-o out.hpp --depfile out.d --base-dir . -I fx/modules --contract fx/contract.json fx/shaders";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto header = dir.path() / "out.hpp";
    const auto data = dir.path() / "out.cpp";
    const std::string first = readFile(data);
    EXPECT_NE(first.find("// ---- sources read (prism-shaderc's no-op check): "), std::string::npos);
    EXPECT_NE(first.find("\n//   fx/modules/fog.glsl\n"), std::string::npos);
    fs::remove(dir.path() / "out.d");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(readFile(data), first);
    EXPECT_NE(readFile(dir.path() / "out.d").find("fx/modules/fog.glsl"), std::string::npos)
        << "the no-op writes the depfile";

    dir.write("fx/modules/fog.glsl", readFile(dir.path() / "fx/modules/fog.glsl") + "// one more comment line\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const std::string edited = readFile(data);
    EXPECT_NE(edited.find("// one more comment line"), std::string::npos);

    // A deleted or overwritten header is rewritten, although the data file's record is current.
    const std::string goodHeader = readFile(header);
    fs::remove(header);
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(readFile(header), goodHeader);
    dir.write("out.hpp", "// an old header\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(readFile(header), goodHeader);

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
    auto header = readFile(dir.path() / "f.cpp");  // the variant table is in the data file
    EXPECT_NE(header.find("\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_EQ(header.find("\"FOG=0,LIGHTS=1\""), std::string::npos);
    EXPECT_EQ(runShaderc("--check --variant tinted:FOG=7 " + fixtureArgs(), dir.str()).exitCode, 1);
}

TEST(ToolVariants, WildcardFilterAndItsTypoCheck) {
    ScratchDir dir("wildcard");
    auto run = runShaderc("--variant '*:LIGHTS=2' -o w.hpp " + fixtureArgs(), dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto header = readFile(dir.path() / "w.cpp");  // the variant table is in the data file
    EXPECT_NE(header.find("\"FOG=1,LIGHTS=2\""), std::string::npos);
    EXPECT_EQ(header.find("LIGHTS=1\""), std::string::npos);
    auto typo = runShaderc("--check --variant '*:LIGTHS=2' " + fixtureArgs(), dir.str());
    EXPECT_EQ(typo.exitCode, 1);
    EXPECT_NE(typo.output.find("no shader declares a variant 'LIGTHS'"), std::string::npos) << typo.output;
}

// Hermetic output: the same sources checked out at two absolute paths of different depth
// give byte-identical headers, data files and emitted GLSL (names are relative to
// --base-dir, and so is everything the fingerprints hash; no command line, no time).
TEST(GoldenHeader, TwoCheckoutsGiveByteIdenticalHeaders) {
    ScratchDir dir("two-checkouts");
    std::string outputs[2];
    const std::string roots[2] = {dir.str() + "/a", dir.str() + "/deeper/checkout/b"};
    for (int i = 0; i < 2; ++i) {
        fs::create_directories(roots[i]);
        fs::copy(kSource + "/modules", roots[i] + "/modules", fs::copy_options::recursive);
        fs::copy(kSource + "/shader_sources", roots[i] + "/shader_sources", fs::copy_options::recursive);
        const std::string args = "-o gen/catalogue.hpp --emit-glsl " + roots[i] + "/glsl --depfile " + roots[i] +
                                 "/c.d --stamp " + roots[i] + "/c.stamp --base-dir " + roots[i] + " -I " + roots[i] +
                                 "/modules --contract " + roots[i] + "/modules/contract.json " + roots[i] +
                                 "/shader_sources";
        auto run = prism::test::runShaderc(args, roots[i]);
        ASSERT_EQ(run.exitCode, 0) << run.output;
        outputs[i] = readFile(fs::path(roots[i]) / "gen/catalogue.hpp") + "\n====\n" +
                     readFile(fs::path(roots[i]) / "gen/catalogue.cpp");
        std::vector<fs::path> glsl;
        for (const auto& e : fs::directory_iterator(roots[i] + "/glsl")) glsl.push_back(e.path().filename());
        std::sort(glsl.begin(), glsl.end());
        for (const auto& f : glsl)
            outputs[i] += "\n==== " + f.string() + "\n" + readFile(roots[i] + "/glsl/" + f.string());
        EXPECT_GT(glsl.size(), 100u);
        EXPECT_EQ(outputs[i].find(roots[i]), std::string::npos) << "an absolute path is embedded";
    }
    EXPECT_FALSE(outputs[0].empty());
    EXPECT_TRUE(outputs[0] == outputs[1]) << "the outputs depend on where the sources are checked out";
}

// The fingerprint hashes only what changes the output: naming a depfile or a stamp, or
// emitting GLSL as well, leaves the header and data bytes unchanged (and so does the
// folder the tool runs in).
TEST(GoldenHeader, BuildSystemOptionsDoNotChangeTheOutputs) {
    ScratchDir dir("options");
    const std::string base = "--base-dir " + kSource + " -I " + kFixture + "/modules --contract " + kFixture +
                             "/contract.json " + kFixture + "/shaders";
    const std::string extras[] = {"", "--depfile out.d", "--stamp out.stamp", "--emit-glsl glsl",
                                  "--depfile x/y.d --stamp z.stamp --emit-glsl g2 -j 1"};
    std::string first;
    for (int i = 0; i < 5; ++i) {
        const auto sub = dir.path() / std::to_string(i);
        fs::create_directories(sub);
        auto run = runShaderc("-o out.hpp " + extras[i] + " " + base, sub.string());
        ASSERT_EQ(run.exitCode, 0) << extras[i] << "\n" << run.output;
        const auto bytes = readFile(sub / "out.hpp") + "\n====\n" + readFile(sub / "out.cpp");
        if (i == 0) first = bytes;
        EXPECT_TRUE(bytes == first) << "'" << extras[i] << "' changed the header or data bytes";
    }
    EXPECT_EQ(first.find("Command"), std::string::npos) << "no command line in the outputs";
}

// Issue 10, item 1: a text-only module edit rewrites the data file and leaves the
// header (and its mtime) alone, so code that includes the header does not recompile;
// a new module changes a declaration (ModuleId) and rewrites the header.
TEST(ToolOutputs, ModuleTextEditRewritesOnlyTheDataFile) {
    ScratchDir dir("split");
    fs::copy(kFixture, dir.path() / "fx", fs::copy_options::recursive);
    const std::string args = "-o gen/out.hpp --base-dir . -I fx/modules --contract fx/contract.json fx/shaders";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto header = dir.path() / "gen/out.hpp", data = dir.path() / "gen/out.cpp";
    const auto headerTime = fs::last_write_time(header);
    const auto headerText = readFile(header), dataText = readFile(data);
    EXPECT_EQ(headerText.find("#version"), std::string::npos) << "the header holds no GLSL";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));

    dir.write("fx/modules/fog.glsl", readFile(dir.path() / "fx/modules/fog.glsl") + "// an edited comment\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_NE(readFile(data), dataText);
    EXPECT_NE(readFile(data).find("// an edited comment"), std::string::npos);
    EXPECT_EQ(readFile(header), headerText);
    EXPECT_EQ(fs::last_write_time(header), headerTime) << "a module text edit rewrote the header";

    dir.write("fx/modules/extra.glsl", "// Provides: a module nobody includes yet.\nfloat extra() { return 1.0; }\n");
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_NE(readFile(header).find("    extra = "), std::string::npos);
}

// Issue 10, item 2: each module text is stored once, so the project catalogue's data is
// at most a quarter of the 1.2 MB the one-header layout took (module texts per variant).
TEST(ToolOutputs, ProjectCatalogueStoresEachModuleOnce) {
    ScratchDir dir("size");
    auto run = runShaderc("-o catalogue.hpp --base-dir " + kSource + " -I " + kSource + "/modules --contract " +
                              kSource + "/modules/contract.json " + kSource + "/shader_sources",
                          dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto bytes = fs::file_size(dir.path() / "catalogue.hpp") + fs::file_size(dir.path() / "catalogue.cpp");
    EXPECT_LE(bytes, 1200u * 1000u / 4) << "generated bytes";
    // A line only modules/lighting.glsl has, used by most of the 150+ variants, appears once.
    const auto data = readFile(dir.path() / "catalogue.cpp");
    const std::string line = "vec3 specularTerm(vec3 toLight, vec3 toEye, vec3 normal) {";
    ASSERT_NE(readFile(kSource + "/modules/lighting.glsl").find(line), std::string::npos);
    std::size_t n = 0;
    for (auto pos = data.find(line); pos != std::string::npos; pos = data.find(line, pos + 1)) ++n;
    EXPECT_EQ(n, 1u);
}

// Modules found outside --base-dir (an installed Prism's modules, say) are named relative
// to the -I directory that found them, in the outputs and in the no-op record, so the
// outputs do not depend on where that directory lies relative to the project; and the
// no-op still finds those files to hash them.
TEST(GoldenHeader, ModulesOutsideTheBaseDirAreNamedByTheirIncludeDir) {
    ScratchDir dir("outside");
    std::string outputs[2];
    const std::string projects[2] = {dir.str() + "/one/proj", dir.str() + "/two/a/b/proj"};
    const std::string prefixes[2] = {dir.str() + "/one/prefix/modules", dir.str() + "/two/x/modules"};
    for (int i = 0; i < 2; ++i) {
        fs::create_directories(projects[i]);
        fs::create_directories(fs::path(prefixes[i]).parent_path());
        fs::copy(kFixture + "/modules", prefixes[i], fs::copy_options::recursive);
        fs::copy(kFixture + "/shaders", projects[i] + "/shaders", fs::copy_options::recursive);
        fs::copy(kFixture + "/contract.json", projects[i] + "/contract.json");
        const std::string args = "-o gen/out.hpp --depfile out.d --base-dir " + projects[i] + " -I " + prefixes[i] +
                                 " --contract contract.json shaders";
        auto run = runShaderc(args, projects[i]);
        ASSERT_EQ(run.exitCode, 0) << run.output;
        outputs[i] = readFile(projects[i] + "/gen/out.hpp") + readFile(projects[i] + "/gen/out.cpp");
        EXPECT_EQ(outputs[i].find(".."), std::string::npos) << "a path climbs out of the base dir";
        EXPECT_NE(outputs[i].find("\"fog.glsl\""), std::string::npos) << "fog.glsl is named by its -I directory";
        EXPECT_NE(outputs[i].find("\n//   @I0/fog.glsl\n"), std::string::npos);

        // The no-op hashes the module through its record: an edit there is noticed.
        const auto before = fs::last_write_time(projects[i] + "/gen/out.cpp");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        fs::remove(projects[i] + "/out.d");
        ASSERT_EQ(runShaderc(args, projects[i]).exitCode, 0);
        EXPECT_EQ(fs::last_write_time(projects[i] + "/gen/out.cpp"), before);
        EXPECT_NE(readFile(projects[i] + "/out.d").find(prefixes[i] + "/fog.glsl"), std::string::npos);
        prism::test::writeFile(prefixes[i] + "/fog.glsl", readFile(prefixes[i] + "/fog.glsl") + "// edited outside\n");
        ASSERT_EQ(runShaderc(args, projects[i]).exitCode, 0);
        EXPECT_NE(readFile(projects[i] + "/gen/out.cpp").find("// edited outside"), std::string::npos);
        prism::test::writeFile(prefixes[i] + "/fog.glsl", readFile(kFixture + "/modules/fog.glsl"));
        ASSERT_EQ(runShaderc(args, projects[i]).exitCode, 0);
        outputs[i] = readFile(projects[i] + "/gen/out.hpp") + readFile(projects[i] + "/gen/out.cpp");
    }
    EXPECT_TRUE(outputs[0] == outputs[1]) << "the outputs depend on where the -I directory lies";
}

// The no-op reads only the end of a large data file (over the 64 KB it reads), and
// still stops there: a full run prints the warning about the module without a leading
// comment, the no-op prints nothing and rewrites nothing.
TEST(ToolOutputs, NoOpOnALargeDataFileStopsBeforeResolving) {
    ScratchDir dir("large");
    fs::copy(kFixture, dir.path() / "fx", fs::copy_options::recursive);
    std::string big = "float bigValue() { return 1.0; }\n";
    for (int i = 0; i < 4000; ++i)
        big += "// filler line " + std::to_string(i) + " of a big module, so that the data file is large\n";
    dir.write("fx/modules/big.glsl", big);
    const std::string args = "-o out.hpp --base-dir . -I fx/modules --contract fx/contract.json fx/shaders";
    auto full = runShaderc(args, dir.str());
    ASSERT_EQ(full.exitCode, 0) << full.output;
    EXPECT_NE(full.output.find("big.glsl"), std::string::npos) << "the full run warns about big.glsl";
    ASSERT_GT(fs::file_size(dir.path() / "out.cpp"), 256u * 1024u);
    const auto before = fs::last_write_time(dir.path() / "out.cpp");
    auto noop = runShaderc(args, dir.str());
    EXPECT_EQ(noop.exitCode, 0);
    EXPECT_EQ(noop.output, "") << "the no-op resolved the catalogue";
    EXPECT_EQ(fs::last_write_time(dir.path() / "out.cpp"), before);
}
