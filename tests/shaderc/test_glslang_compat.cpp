// Differential tests against glslang (issue 17): for each pattern of real module
// libraries in fixtures/compat/, `glslangValidator -E` on the original stage and on
// prism-shaderc's flattened, driver-safe output must give the same active code, and
// glslang must include the same set of files that prism-shaderc flattened in. A
// generated set of conditional-include shaders does the same for many #if forms.
// So every expectation here comes from the compiler.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "include_resolver.hpp"
#include "source_reader.hpp"
#include "tool_runner.hpp"

namespace fs = std::filesystem;

namespace prism::shaderc {
namespace {

const fs::path kCompat = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/compat";

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

// The code lines of a preprocessed text (directives and blank lines dropped).
std::string activeCode(const std::string& preprocessed) {
    std::istringstream in(preprocessed);
    std::string line, code;
    while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        code += line.substr(first) + "\n";
    }
    return code;
}

// Canonical paths of the files glslang's -E output says it included.
std::set<std::string> filesGlslangIncluded(const std::string& preprocessed, const fs::path& stage) {
    static const std::regex lineDirective(R"re(#line \d+ "([^"]+)")re");
    std::set<std::string> files;
    for (std::sregex_iterator it(preprocessed.begin(), preprocessed.end(), lineDirective), end; it != end; ++it) {
        const auto path = fs::weakly_canonical((*it)[1].str()).generic_string();
        if (path != fs::weakly_canonical(stage).generic_string()) files.insert(path);
    }
    return files;
}

struct CompatCase {
    std::string name;
    fs::path stage;  // absolute
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;
};

std::string glslangFlags(const CompatCase& c, bool withDefines) {
    std::string flags;
    for (const auto& dir : c.includeDirs) flags += " -I" + quoted(dir);
    if (withDefines)
        for (const auto& [name, value] : c.defines) flags += " " + quoted("-D" + name + "=" + value);
    return flags;
}

// Runs both sides of one case and compares them; returns glslang's active code.
std::string expectSameAsGlslang(const CompatCase& c) {
    SCOPED_TRACE(c.name);
    const auto original =
        prism::test::runShell("glslangValidator -E" + glslangFlags(c, true) + " " + quoted(c.stage.string()));
    EXPECT_EQ(original.exitCode, 0) << "glslang rejects the fixture itself:\n" << original.output;

    ResolveOptions options;
    options.includeDirs = c.includeDirs;
    options.defines = c.defines;
    DiskReader reader;
    const auto resolved = resolveStage(c.stage.string(), options, reader);
    std::string messages;
    for (const auto& d : resolved.diagnostics) messages += formatDiagnostic(d, ErrorFormat::Gcc);
    EXPECT_TRUE(resolved.ok) << messages;

    prism::test::ScratchDir scratch("compat-" + c.name);
    const fs::path flattened = scratch.path() / ("flat" + c.stage.extension().string());
    prism::test::writeFile(flattened, resolved.stage.text);
    const auto emitted = prism::test::runShell("glslangValidator -E " + quoted(flattened.string()));
    EXPECT_EQ(emitted.exitCode, 0) << emitted.output;
    EXPECT_EQ(activeCode(emitted.output), activeCode(original.output))
        << "prism-shaderc's output takes other branches than glslang on the original";
    const auto compiled = prism::test::runShell("glslangValidator -l " + quoted(flattened.string()));
    EXPECT_EQ(compiled.exitCode, 0) << "the flattened stage does not compile:\n" << compiled.output;

    std::set<std::string> prismFiles;
    for (std::size_t i = 1; i < resolved.stage.files.size(); ++i)
        prismFiles.insert(fs::weakly_canonical(resolved.stage.files[i].canonical).generic_string());
    EXPECT_EQ(prismFiles, filesGlslangIncluded(original.output, c.stage));
    EXPECT_FALSE(activeCode(original.output).empty());
    return activeCode(original.output);
}

CompatCase fixture(const std::string& name, const std::string& stage, std::vector<std::string> includeDirs = {},
                   std::vector<std::pair<std::string, std::string>> defines = {}) {
    for (auto& dir : includeDirs) dir = (kCompat / dir).string();
    return {name, kCompat / stage, std::move(includeDirs), std::move(defines)};
}

TEST(GlslangCompat, GlslangValidatorIsInstalled) {
    // Not a skip: without the reference compiler these tests would prove nothing.
    ASSERT_EQ(prism::test::runShell("glslangValidator --version").exitCode, 0)
        << "install glslang-tools (scripts/setup.sh)";
}

TEST(GlslangCompat, RelativeIncludesGuardsAndDefaults) {
    const auto code = expectSameAsGlslang(fixture("relative", "relative_guards/shaders/main.frag"));
    const auto gles = expectSameAsGlslang(
        fixture("relative-gles", "relative_guards/shaders/main.frag", {}, {{"PLATFORM_GLES", "1"}}));
    EXPECT_NE(code, gles);  // the -D platform switch reaches into a module
}

TEST(GlslangCompat, DuplicateBaseNamesInDifferentFolders) {
    expectSameAsGlslang(fixture("duplicates", "duplicate_names/shaders/main.frag"));
}

TEST(GlslangCompat, GuardedMutualAndSelfIncludesAreNoCycle) {
    expectSameAsGlslang(fixture("mutual", "guarded_mutual/shaders/main.frag"));
}

TEST(GlslangCompat, AncestorFolderLookup) {
    expectSameAsGlslang(fixture("ancestor", "ancestor_lookup/shaders/main.frag"));
}

TEST(GlslangCompat, RootRelativeIncludes) {
    expectSameAsGlslang(fixture("root", "root_relative/root/shaders/main.frag", {"root_relative/root"}));
}

TEST(GlslangCompat, FunctionLikeMacros32BitArithmeticPredefinedMacrosAndComments) {
    const auto plain = expectSameAsGlslang(fixture("conditions", "conditions/shaders/main.frag"));
    const auto fast =
        expectSameAsGlslang(fixture("conditions-fast", "conditions/shaders/main.frag", {}, {{"USE_FAST", "1"}}));
    expectSameAsGlslang(fixture("conditions-gles", "conditions/shaders/main.frag", {}, {{"PLATFORM_GLES", "1"}}));
    EXPECT_NE(plain, fast);  // the optional include under a commented condition flips
}

TEST(GlslangCompat, UnusedBrokenModuleDoesNotMatter) {
    expectSameAsGlslang(fixture("unused", "unused_broken/shaders/main.frag", {"unused_broken/modules"}));
    // The module really is broken, as glslang sees it.
    const auto broken = prism::test::runShell("glslangValidator -E " +
                                              quoted((kCompat / "unused_broken/modules/broken.glsl").string()));
    EXPECT_NE(broken.exitCode, 0) << broken.output;
}

TEST(GlslangCompat, XMacroTemplateIncludedTwice) {
    const auto code = expectSameAsGlslang(fixture("xmacro", "xmacro/shaders/main.frag"));
    EXPECT_NE(code.find("field_green"), std::string::npos);
}

TEST(GlslangCompat, SeventyDeepChain) {
    prism::test::ScratchDir dir("compat-deep");
    dir.write("main.frag",
              "#version 330 core\n#extension GL_GOOGLE_include_directive : require\n#include \"d1.glsl\"\n"
              "out vec4 o;\nvoid main() { o = vec4(deepest()); }\n");
    for (int i = 1; i < 70; ++i)
        dir.write("d" + std::to_string(i) + ".glsl", "#include \"d" + std::to_string(i + 1) + ".glsl\"\n");
    dir.write("d70.glsl", "float deepest() { return 70.0; }\n");
    expectSameAsGlslang({"deep", dir.path() / "main.frag", {}, {}});
}

// A generated set of conditional-include shaders: each #if form below guards an
// include, under several -D settings, and glslang decides on both sides.
TEST(GlslangCompat, GeneratedConditionalIncludes) {
    const std::vector<std::string> conditions = {
        "A",
        "!A",
        "defined(A) && !defined B",
        "A + B * 2 == 5",
        "(A << 30) < 0",
        "(2147483647 + A) < 0",
        "-2147483648 / -1 != 0 || 1",
        "0x7FFFFFFF + A > 0",
        "07 == 7 && 0x10 == 16",
        "ADD(A, B) == 4",
        "ADD(A, ADD(B, 4)) == 9",
        "PAIR == 3",
        "(A | B) ^ 1",
        "~A == -2",
        "A % 2 == 1 && B / 2 == 1",
        "__VERSION__ > 400 && GL_core_profile",
        "defined(GL_ES) || defined GL_compatibility_profile",
        "A /* a comment */ && B",
        "__LINE__ > 10",
    };
    const std::vector<std::vector<std::pair<std::string, std::string>>> settings = {
        {}, {{"A", "1"}}, {{"A", "1"}, {"B", "3"}}, {{"A", "3"}, {"B", "2"}}};
    prism::test::ScratchDir dir("compat-generated");
    std::string stage =
        "#version 450 core\n#extension GL_GOOGLE_include_directive : require\n"
        "#define ADD(x, y) ((x) + (y))\n#define PAIR A + B\n";
    for (std::size_t i = 0; i < conditions.size(); ++i) {
        const std::string file = "c" + std::to_string(i) + ".glsl";
        stage += "#if " + conditions[i] + "\n#include \"" + file + "\"\n#else\nint not_taken_" + std::to_string(i) +
                 ";\n#endif\n";
        dir.write(file, "int taken_" + std::to_string(i) + ";\n");
    }
    stage += "out vec4 o;\nvoid main() { o = vec4(1.0); }\n";
    dir.write("main.frag", stage);
    std::set<std::string> distinct;
    for (std::size_t s = 0; s < settings.size(); ++s)
        distinct.insert(
            expectSameAsGlslang({"generated" + std::to_string(s), dir.path() / "main.frag", {}, settings[s]}));
    EXPECT_EQ(distinct.size(), settings.size());  // every setting takes other branches
}

// ---- the catalogue: module names and unused modules ---------------------------------------

TEST(GlslangCompat, SameBaseNameModulesGetPathNames) {
    prism::test::ScratchDir out("compat-names");
    const auto run = prism::test::runShaderc("-o " + (out.path() / "h.hpp").string() + " --base-dir " +
                                             kCompat.string() + " " + (kCompat / "duplicate_names/shaders").string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string header = prism::test::readFile(out.path() / "h.hpp");
    EXPECT_NE(header.find("    a__util = 0,  // duplicate_names/shaders/a/util.glsl"), std::string::npos) << header;
    EXPECT_NE(header.find("    b__util = 1,  // duplicate_names/shaders/b/util.glsl"), std::string::npos);
}

TEST(GlslangCompat, SameRelativePathUnderTwoIncludeDirsIsAWarningNotAnError) {
    prism::test::ScratchDir dir("compat-two-roots");
    dir.write("a/util.glsl", "// util of a.\nfloat util_a() { return 1.0; }\n");
    dir.write("b/util.glsl", "// util of b.\nfloat util_b() { return 2.0; }\n");
    dir.write("s/main.vert",
              "#version 330 core\nin vec3 a_position;\nvoid main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("s/main.frag",
              "#version 330 core\n#include \"../b/util.glsl\"\nout vec4 o;\nvoid main() { o = vec4(util_b()); }\n");
    const auto run = prism::test::runShaderc("-o h.hpp --base-dir . -I a -I b s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("b/util.glsl: warning: module name 'util' is taken by a module under an earlier root; "
                              "this one is 'b__util'"),
              std::string::npos)
        << run.output;
    const std::string header = prism::test::readFile(dir.path() / "h.hpp");
    EXPECT_NE(header.find("    b__util = 0,  // b/util.glsl"), std::string::npos) << header;
    EXPECT_NE(header.find("    util = 1,  // a/util.glsl"), std::string::npos);
}

// Issue 37, item 7: a user's module that an earlier include dir's module of the same name
// hides is a warning naming both paths, even when nothing includes either.
TEST(GlslangCompat, AShadowedModuleThatNothingIncludesIsAWarningNamingBothPaths) {
    prism::test::ScratchDir dir("compat-shadowed");
    dir.write("prism/fog.glsl", "// Prism's fog.\nfloat fog_prism() { return 1.0; }\n");
    dir.write("mine/fog.glsl", "// The user's fog.\nfloat fog_mine() { return 2.0; }\n");
    dir.write("mine/rim.glsl", "// The user's rim.\nfloat rim() { return 3.0; }\n");
    dir.write("s/main.vert",
              "#version 330 core\nin vec3 a_position;\nvoid main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("s/main.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    const auto run = prism::test::runShaderc("-o h.hpp --base-dir . -I prism -I mine s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("mine/fog.glsl: warning: module 'fog.glsl' is shadowed by prism/fog.glsl (an earlier "
                              "include dir)"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("rim.glsl: warning"), std::string::npos) << run.output;  // not shadowed: no word
    const std::string header = prism::test::readFile(dir.path() / "h.hpp");
    EXPECT_EQ(header.find("mine/fog.glsl"), std::string::npos) << header;  // what the warning says: left out
}

TEST(GlslangCompat, ProblemsInUnusedModulesAreWarnings) {
    const auto run = prism::test::runShaderc("--check -I " + (kCompat / "unused_broken/modules").string() + " " +
                                             (kCompat / "unused_broken/shaders").string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("broken.glsl:2:10: warning: cannot find include \"missing.glsl\""), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("which no stage includes, so a warning"), std::string::npos);

    // Once a stage includes it, the same problem is an error.
    prism::test::ScratchDir dir("compat-used-broken");
    dir.write("s/main.vert", prism::test::readFile(kCompat / "unused_broken/shaders/main.vert"));
    dir.write("s/main.frag",
              "#version 330 core\n#include \"broken.glsl\"\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    const auto used = prism::test::runShaderc("--check -I " + (kCompat / "unused_broken/modules").string() + " " +
                                              (dir.path() / "s").string());
    EXPECT_EQ(used.exitCode, 1) << used.output;
    EXPECT_NE(used.output.find("broken.glsl:2:10: error: cannot find include \"missing.glsl\""), std::string::npos)
        << used.output;
}

}  // namespace
}  // namespace prism::shaderc
