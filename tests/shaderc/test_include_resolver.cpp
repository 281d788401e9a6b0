// Unit tests of the include resolver (stage 2 of prism-shaderc) on in-memory files,
// plus glslang checks that the emitted #line directives give true line numbers.
#include <gtest/gtest.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "glslang_preprocessor.hpp"
#include "include_resolver.hpp"
#include "include_search.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {
namespace {

// Substring checks that print both strings on failure (gmock is not linked).
::testing::AssertionResult contains(const std::string& text, const std::string& needle) {
    if (text.find(needle) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "\"" << needle << "\" not found in:\n" << text;
}

::testing::AssertionResult lacks(const std::string& text, const std::string& needle) {
    if (text.find(needle) == std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "\"" << needle << "\" unexpectedly found in:\n" << text;
}

ResolveResult resolve(const MemoryReader& reader, const std::string& stage, const ResolveOptions& options = {}) {
    return resolveStage(stage, options, reader);
}

std::string allMessages(const std::vector<Diagnostic>& diagnostics) {
    std::string text;
    for (const auto& d : diagnostics) text += formatDiagnostic(d, ErrorFormat::Gcc);
    return text;
}

std::size_t countOf(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
    return count;
}

Diagnostic onlyError(const ResolveResult& result) {
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.diagnostics.size(), 1u) << allMessages(result.diagnostics);
    return result.diagnostics.at(0);
}

// ---- paths -----------------------------------------------------------------------------

TEST(SourcePaths, JoinAndParentAreLexical) {
    EXPECT_EQ(joinPath("shaders", "../modules/x.glsl"), "modules/x.glsl");
    EXPECT_EQ(joinPath("shaders/", "./x.glsl"), "shaders/x.glsl");
    EXPECT_EQ(joinPath("", "a/./b/../c.glsl"), "a/c.glsl");
    EXPECT_EQ(joinPath("dir", "/abs/x.glsl"), "/abs/x.glsl");
    EXPECT_EQ(joinPath("a\\b", "c.glsl"), "a/b/c.glsl");
    EXPECT_EQ(parentDir("shaders/main.frag"), "shaders");
    EXPECT_EQ(parentDir("main.frag"), "");
    EXPECT_EQ(parentDir("/main.frag"), "/");
}

TEST(SourcePaths, MemoryReaderNormalisesKeys) {
    MemoryReader reader{{"a/./b/../c.glsl", "x"}};
    EXPECT_EQ(reader.canonical("a/c.glsl"), "a/c.glsl");
    EXPECT_EQ(reader.read("./a/c.glsl"), "x");
    EXPECT_FALSE(reader.canonical("a/b/c.glsl"));
}

// ---- include once, diamonds, cycles ----------------------------------------------------

TEST(IncludeResolver, IncludeOnceSkipsRepeats) {
    MemoryReader reader{{"main.frag", "#include \"a.glsl\"\n#include \"a.glsl\"\nvoid main() {}\n"},
                        {"a.glsl", "float aFunction() { return 1.0; }\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(countOf(result.stage.text, "aFunction"), 1u);
    EXPECT_EQ(result.stage.files.size(), 2u);
    EXPECT_EQ(result.stage.filesRead, (std::vector<std::string>{"main.frag", "a.glsl"}));
}

TEST(IncludeResolver, DiamondIncludesSharedModuleOnce) {
    MemoryReader reader{{"a.frag", "#include \"b.glsl\"\n#include \"c.glsl\"\nvoid main() {}\n"},
                        {"b.glsl", "#include \"d.glsl\"\nfloat bFn() { return dFn(); }\n"},
                        {"c.glsl", "#include \"d.glsl\"\nfloat cFn() { return dFn(); }\n"},
                        {"d.glsl", "float dFn() { return 1.0; }\n"}};
    const auto result = resolve(reader, "a.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(countOf(result.stage.text, "float dFn()"), 1u);
    EXPECT_LT(result.stage.text.find("float dFn()"), result.stage.text.find("float bFn()"));
    EXPECT_LT(result.stage.text.find("float bFn()"), result.stage.text.find("float cFn()"));
    EXPECT_EQ(result.stage.filesRead, (std::vector<std::string>{"a.frag", "b.glsl", "d.glsl", "c.glsl"}));
    ASSERT_EQ(result.stage.files.size(), 4u);
    EXPECT_EQ(result.stage.files[2].path, "d.glsl");
    EXPECT_EQ(result.stage.files[2].number, 2u);
    EXPECT_EQ(result.stage.files[2].chain, (std::vector<IncludeSite>{{"b.glsl", 1}, {"a.frag", 1}}));
}

TEST(IncludeResolver, CycleIsAnErrorWithTheChain) {
    MemoryReader reader{{"main.frag", "#include \"a.glsl\"\nvoid main() {}\n"},
                        {"a.glsl", "// a\n#include \"b.glsl\"\n"},
                        {"b.glsl", "// b\n\n#include \"a.glsl\"\n"}};
    const auto started = std::chrono::steady_clock::now();
    const auto result = resolve(reader, "main.frag");
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(2));
    const Diagnostic& error = onlyError(result);
    EXPECT_TRUE(contains(error.message, "include cycle: a.glsl -> b.glsl -> a.glsl;"));
    EXPECT_EQ(error.file, "b.glsl");
    EXPECT_EQ(error.line, 3);
    EXPECT_EQ(error.column, 10);
    EXPECT_EQ(error.includedFrom, (std::vector<IncludeSite>{{"a.glsl", 2}, {"main.frag", 1}}));
}

TEST(IncludeResolver, SelfIncludeIsACycle) {
    MemoryReader reader{{"main.frag", "#include \"self.glsl\"\n"}, {"self.glsl", "#include \"self.glsl\"\n"}};
    EXPECT_TRUE(contains(onlyError(resolve(reader, "main.frag")).message, "include cycle: self.glsl -> self.glsl;"));

    MemoryReader stageOnly{{"main.frag", "#include \"main.frag\"\n"}};
    EXPECT_TRUE(contains(onlyError(resolve(stageOnly, "main.frag")).message, "include cycle: main.frag -> main.frag;"));
}

TEST(IncludeResolver, CycleCheckedBeforeIncludeOnce) {
    // b.glsl is entered (and still open) when c.glsl includes it again.
    MemoryReader reader{{"main.frag", "#include \"b.glsl\"\n"},
                        {"b.glsl", "#include \"c.glsl\"\n"},
                        {"c.glsl", "#include \"b.glsl\"\n"}};
    EXPECT_TRUE(contains(onlyError(resolve(reader, "main.frag")).message, "include cycle"));
}

std::string chainFileName(int index) {
    return std::string("f").append(std::to_string(index)).append(".glsl");
}

// main.frag -> f1 -> ... -> f<depth>: `depth` files nested below the stage.
MemoryReader chainOfDepth(int depth) {
    MemoryReader reader{{"main.frag", "#include \"f1.glsl\"\nvoid main() {}\n"}};
    for (int i = 1; i < depth; ++i)
        reader.add(chainFileName(i), std::string("#include \"").append(chainFileName(i + 1)).append("\"\n"));
    reader.add(chainFileName(depth), "float deepest;\n");
    return reader;
}

TEST(IncludeResolver, DepthLimitIs256Files) {
    const auto deepest = resolve(chainOfDepth(256), "main.frag");  // glslang takes 256 too
    ASSERT_TRUE(deepest.ok) << allMessages(deepest.diagnostics);
    EXPECT_TRUE(contains(deepest.stage.text, "float deepest;"));

    const Diagnostic& error = onlyError(resolve(chainOfDepth(257), "main.frag"));
    EXPECT_TRUE(contains(error.message, "nested more than 256 files deep (limit): main.frag -> f1.glsl"));
    EXPECT_TRUE(
        contains(error.message, "... (248 more) -> f253.glsl -> f254.glsl -> f255.glsl -> f256.glsl -> f257.glsl"));
    EXPECT_EQ(error.file, "f256.glsl");
}

// ---- missing and malformed includes ----------------------------------------------------

TEST(IncludeResolver, MissingIncludeNamesFileLineAndSearchedDirs) {
    MemoryReader reader{{"shaders/main.frag", "#version 330 core\n\n  #include \"lighting.glsl\"\n"}};
    ResolveOptions options;
    options.includeDirs = {"modules", "third_party/glsl"};
    const Diagnostic& error = onlyError(resolve(reader, "shaders/main.frag", options));
    EXPECT_EQ(error.file, "shaders/main.frag");
    EXPECT_EQ(error.line, 3);
    EXPECT_EQ(error.column, 12);
    EXPECT_TRUE(contains(error.message, "\"lighting.glsl\""));
    const auto own = error.message.find("shaders (the including file's folder)");
    const auto first = error.message.find("modules");
    const auto second = error.message.find("third_party/glsl");
    EXPECT_NE(own, std::string::npos);
    EXPECT_LT(own, first);
    EXPECT_LT(first, second);
    EXPECT_NE(second, std::string::npos);
    EXPECT_TRUE(contains(error.message, "add a -I directory or fix the path"));
}

TEST(IncludeResolver, MissingAngleIncludeDoesNotSearchIncluderDir) {
    MemoryReader reader{{"shaders/main.frag", "#include <x.glsl>\n"}, {"shaders/x.glsl", "float x;\n"}};
    ResolveOptions options;
    options.includeDirs = {"inc"};
    const Diagnostic& error = onlyError(resolve(reader, "shaders/main.frag", options));
    EXPECT_TRUE(contains(error.message, "searched: inc (-I);"));
    EXPECT_TRUE(lacks(error.message, "including file's folder"));
}

TEST(IncludeResolver, MalformedIncludeIsAnErrorAtItsLine) {
    for (const char* line : {"#include lighting.glsl", "#include \"unterminated.glsl", "#include", "#include \"\"",
                             "#include \"a.glsl\" junk"}) {
        MemoryReader reader{{"main.frag", std::string("// x\n") + line + "\n"}, {"a.glsl", ""}};
        const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
        EXPECT_EQ(error.line, 2) << line;
        EXPECT_TRUE(contains(error.message, "malformed #include")) << line;
    }
}

TEST(IncludeResolver, ErrorInsideIncludeCarriesIncludedFrom) {
    MemoryReader reader{{"main.frag", "\n#include \"a.glsl\"\n"}, {"a.glsl", "#include \"gone.glsl\"\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_EQ(error.file, "a.glsl");
    EXPECT_EQ(error.line, 1);
    EXPECT_EQ(error.includedFrom, (std::vector<IncludeSite>{{"main.frag", 2}}));
}

// ---- conditionals ----------------------------------------------------------------------

const char* kFogStage =
    "#version 330 core\n"
    "#ifdef USE_FOG\n"
    "#include \"fog.glsl\"\n"
    "#endif\n"
    "void main() {}\n";

TEST(IncludeResolver, IncludeInDisabledBranchIsNotFollowed) {
    MemoryReader reader{{"main.frag", kFogStage}};  // fog.glsl does not exist
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.filesRead, std::vector<std::string>{"main.frag"});
    EXPECT_TRUE(contains(result.stage.text, "#ifdef USE_FOG\n\n#endif\n"));
    EXPECT_TRUE(lacks(result.stage.text, "#include"));
}

TEST(IncludeResolver, IncludeFollowedWhenEnabledByOptionDefine) {
    MemoryReader reader{{"main.frag", kFogStage}, {"fog.glsl", "float fogFactor() { return 0.5; }\n"}};
    ResolveOptions options;
    options.defines = {{"USE_FOG", ""}};
    const auto result = resolve(reader, "main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "fogFactor"));
    EXPECT_TRUE(contains(result.stage.text, "#define USE_FOG\n"));
}

TEST(IncludeResolver, IncludeFollowedWhenEnabledByEarlierDefine) {
    MemoryReader reader{{"main.frag", std::string("#define USE_FOG 1\n") + kFogStage},
                        {"fog.glsl", "float fogFactor() { return 0.5; }\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "fogFactor"));
}

TEST(IncludeResolver, UndefDisablesLaterInclude) {
    MemoryReader reader{{"main.frag", std::string("#define USE_FOG\n#undef USE_FOG\n") + kFogStage}};
    EXPECT_TRUE(resolve(reader, "main.frag").ok);
}

TEST(IncludeResolver, DefinesInIncludedFileAffectLaterConditions) {
    MemoryReader reader{{"main.frag", "#include \"config.glsl\"\n#if SHADOWS > 1\n#include \"pcf.glsl\"\n#endif\n"},
                        {"config.glsl", "#define SHADOWS 2\n"},
                        {"pcf.glsl", "float pcf;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "float pcf;"));
}

TEST(IncludeResolver, ElifChainFollowsOnlyTheTakenBranch) {
    const std::string stage =
        "#if QUALITY == 0\n#include \"low.glsl\"\n"
        "#elif QUALITY == 1\n#include \"mid.glsl\"\n"
        "#else\n#include \"high.glsl\"\n#endif\n";
    MemoryReader reader{
        {"main.frag", stage}, {"low.glsl", "int low;\n"}, {"mid.glsl", "int mid;\n"}, {"high.glsl", "int high;\n"}};
    for (const auto& [quality, expected] :
         std::vector<std::pair<std::string, std::string>>{{"0", "low.glsl"}, {"1", "mid.glsl"}, {"7", "high.glsl"}}) {
        ResolveOptions options;
        options.defines = {{"QUALITY", quality}};
        const auto result = resolve(reader, "main.frag", options);
        ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
        EXPECT_EQ(result.stage.filesRead, (std::vector<std::string>{"main.frag", expected})) << quality;
    }
}

TEST(IncludeResolver, VersionMacrosUsableInConditions) {
    MemoryReader reader{{"main.frag",
                         "#version 450 core\n#if __VERSION__ >= 450 && GL_core_profile\n"
                         "#include \"modern.glsl\"\n#endif\n"},
                        {"modern.glsl", "int modern;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "int modern;"));
}

TEST(IncludeResolver, UnterminatedIfNamesItsLine) {
    MemoryReader reader{{"main.frag", "#include \"a.glsl\"\n"}, {"a.glsl", "\n\n#ifdef X\nint a;\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_EQ(error.file, "a.glsl");
    EXPECT_EQ(error.line, 3);
    EXPECT_TRUE(contains(error.message, "unterminated #ifdef"));
}

TEST(IncludeResolver, UnbalancedEndifAndElseAreErrors) {
    MemoryReader reader{{"main.frag", "int a;\n#endif\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_EQ(error.line, 2);
    EXPECT_EQ(error.message, "#endif without #if");

    MemoryReader elseReader{{"main.frag", "#else\n"}};
    EXPECT_EQ(onlyError(resolve(elseReader, "main.frag")).message, "#else without #if");
}

TEST(IncludeResolver, DivisionByZeroInConditionIsAnError) {
    MemoryReader reader{{"main.frag", "#if 4 / (2 - 2)\n#endif\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_TRUE(contains(error.message, "division by 0"));  // glslang's own words
    EXPECT_EQ(error.line, 1);
}

// ---- search order ----------------------------------------------------------------------

TEST(IncludeResolver, QuotedSearchesIncluderDirFirstAngleOnlyIncludeDirs) {
    MemoryReader reader{{"shaders/quoted.frag", "#include \"common.glsl\"\n"},
                        {"shaders/angled.frag", "#include <common.glsl>\n"},
                        {"shaders/common.glsl", "int fromShaders;\n"},
                        {"inc/common.glsl", "int fromInc;\n"}};
    ResolveOptions options;
    options.includeDirs = {"inc"};
    const auto quoted = resolve(reader, "shaders/quoted.frag", options);
    const auto angled = resolve(reader, "shaders/angled.frag", options);
    ASSERT_TRUE(quoted.ok && angled.ok);
    EXPECT_EQ(quoted.stage.files.at(1).path, "shaders/common.glsl");
    EXPECT_TRUE(contains(quoted.stage.text, "fromShaders"));
    EXPECT_EQ(angled.stage.files.at(1).path, "inc/common.glsl");
    EXPECT_TRUE(contains(angled.stage.text, "fromInc"));
}

TEST(IncludeResolver, IncludeDirsSearchedInOrderAndRelativeToIncluder) {
    MemoryReader reader{{"s/main.frag", "#include <lib/a.glsl>\n"},
                        {"first/lib/a.glsl", "#include \"b.glsl\"\n"},
                        {"first/lib/b.glsl", "int firstB;\n"},
                        {"second/lib/a.glsl", "int secondA;\n"}};
    ResolveOptions options;
    options.includeDirs = {"first", "second"};
    const auto result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.filesRead,
              (std::vector<std::string>{"s/main.frag", "first/lib/a.glsl", "first/lib/b.glsl"}));
}

TEST(IncludeResolver, SameFileThroughDifferentSpellingsEntersOnce) {
    MemoryReader reader{{"s/main.frag", "#include \"../m/a.glsl\"\n#include <a.glsl>\n"}, {"m/a.glsl", "int once;\n"}};
    ResolveOptions options;
    options.includeDirs = {"m"};
    const auto result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(countOf(result.stage.text, "int once;"), 1u);
    EXPECT_EQ(result.stage.files.at(1).path, "m/a.glsl");
}

// ---- pragmas, extensions, versions -----------------------------------------------------

TEST(IncludeResolver, PragmaOnceAcceptedAndBlanked) {
    MemoryReader reader{{"main.frag", "#include \"a.glsl\"\n#include \"a.glsl\"\n"},
                        {"a.glsl", "#pragma once\nint a;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(countOf(result.stage.text, "int a;"), 1u);
    EXPECT_TRUE(lacks(result.stage.text, "#pragma once"));
}

TEST(IncludeResolver, IncludeExtensionLinesAreBlanked) {
    MemoryReader reader{{"main.frag",
                         "#version 330 core\n#extension GL_GOOGLE_include_directive : require\n"
                         "#extension GL_ARB_shading_language_include: enable\n"
                         "#extension GL_GOOGLE_cpp_style_line_directive : enable\n"
                         "#extension GL_ARB_separate_shader_objects : enable\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok);
    EXPECT_TRUE(lacks(result.stage.text, "GL_GOOGLE"));
    EXPECT_TRUE(lacks(result.stage.text, "GL_ARB_shading_language_include"));
    EXPECT_TRUE(contains(result.stage.text, "#extension GL_ARB_separate_shader_objects : enable\n"));
}

TEST(IncludeResolver, VersionHoistedFromIncludeWhenStageHasNone) {
    MemoryReader reader{{"main.frag", "#include \"v.glsl\"\nvoid main() {}\n"},
                        {"v.glsl", "#version 450 core\nint v;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(result.stage.versionDirective, "#version 450 core");
    EXPECT_EQ(result.stage.versionNumber, 450);
    EXPECT_TRUE(result.stage.text.starts_with("#version 450 core\n"));
    EXPECT_EQ(countOf(result.stage.text, "#version"), 1u);
}

TEST(IncludeResolver, DefaultVersionWhenNoneFound) {
    MemoryReader reader{{"main.frag", "void main() {}\n"}};
    ResolveOptions options;
    options.defaultVersion = "#version 410 core";
    const auto result = resolve(reader, "main.frag", options);
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(result.stage.versionNumber, 410);
    EXPECT_TRUE(result.stage.text.starts_with("#version 410 core\n#line 1 0\n"));
}

TEST(IncludeResolver, EquivalentVersionsAgree) {
    MemoryReader reader{{"main.frag", "#version 330\n#include \"a.glsl\"\n"}, {"a.glsl", "#version 330 core\n"}};
    const auto result = resolve(reader, "main.frag");
    EXPECT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.versionDirective, "#version 330");
}

TEST(IncludeResolver, ConflictingVersionsNameBothPlaces) {
    MemoryReader reader{{"main.frag", "#version 330 core\n#include \"a.glsl\"\n"},
                        {"a.glsl", "// a\n#version 450 core\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_EQ(error.file, "a.glsl");
    EXPECT_EQ(error.line, 2);
    EXPECT_TRUE(contains(error.message, "#version 450 core conflicts with #version 330 core at main.frag:1"));
    ASSERT_EQ(error.notes.size(), 1u);
    EXPECT_EQ(error.notes[0].file, "main.frag");
    EXPECT_EQ(error.notes[0].line, 1);
}

TEST(IncludeResolver, MalformedVersionIsAnError) {
    MemoryReader reader{{"main.frag", "#version three\n"}};
    EXPECT_TRUE(contains(onlyError(resolve(reader, "main.frag")).message, "malformed #version"));
}

// ---- output layout ---------------------------------------------------------------------

MemoryReader layoutReader(const std::string& version) {
    return MemoryReader{{"main.frag", "#version " + version + "\n#include \"lib.glsl\"\nvoid main() {}\n"},
                        {"lib.glsl", "float f() { return 1.0; }\n"}};
}

TEST(IncludeResolver, LineLayoutFor330) {
    ResolveOptions options;
    options.defines = {{"FOO", "1"}, {"BAR", ""}};
    const auto result = resolve(layoutReader("330 core"), "main.frag", options);
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(result.stage.text,
              "#version 330 core\n"
              "#define FOO 1\n"
              "#define BAR\n"
              "#line 1 0\n"
              "\n"
              "#line 1 1\n"
              "float f() { return 1.0; }\n"
              "#line 3 0\n"
              "void main() {}\n");
    ASSERT_EQ(result.stage.files.size(), 2u);
    EXPECT_EQ(result.stage.files[1].path, "lib.glsl");
    EXPECT_EQ(result.stage.files[1].chain, (std::vector<IncludeSite>{{"main.frag", 2}}));
}

TEST(IncludeResolver, LineLayoutBefore330NamesThePreviousLine) {
    const auto result = resolve(layoutReader("150"), "main.frag");
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(result.stage.text,
              "#version 150\n"
              "#line 0 0\n"
              "\n"
              "#line 0 1\n"
              "float f() { return 1.0; }\n"
              "#line 2 0\n"
              "void main() {}\n");
}

TEST(IncludeResolver, ContinuedIncludeKeepsLineNumbers) {
    MemoryReader reader{{"main.frag", "#include \\\n  \"lib.glsl\"\nint after;\n"}, {"lib.glsl", "int lib;"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "#line 1 1\nint lib;\n#line 3 0\nint after;\n"));
}

TEST(IncludeResolver, CrlfAndNoTrailingNewlineAndEmptyFiles) {
    MemoryReader reader{{"main.frag", "#version 330 core\r\n#include \"empty.glsl\"\r\nint x;"}, {"empty.glsl", ""}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.text, "#version 330 core\n#line 1 0\n\n#line 1 1\n#line 3 0\nint x;\n");
}

TEST(IncludeResolver, IncludeInsideCommentsIsIgnored) {
    MemoryReader reader{{"main.frag",
                         "/* disabled:\n#include \"gone.glsl\"\n*/\n"
                         "// #include \"gone.glsl\"\n"
                         "int a; /* #include \"gone.glsl\" */\n"}};
    const auto result = resolve(reader, "main.frag");
    EXPECT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.filesRead, std::vector<std::string>{"main.frag"});
}

TEST(IncludeResolver, MissingStageFileIsAnError) {
    MemoryReader reader;
    const Diagnostic& error = onlyError(resolve(reader, "nope.frag"));
    EXPECT_EQ(error.file, "nope.frag");
    EXPECT_TRUE(contains(error.message, "not found"));
}

TEST(IncludeResolver, InvalidDefineNameIsAnError) {
    MemoryReader reader{{"main.frag", "int a;\n"}};
    ResolveOptions options;
    options.defines = {{"1BAD", "1"}};
    EXPECT_TRUE(contains(onlyError(resolve(reader, "main.frag", options)).message, "invalid define"));
}

// ---- variant pragmas -------------------------------------------------------------------

TEST(IncludeResolver, VariantPragmasCollectedAndBlanked) {
    MemoryReader reader{{"main.frag", "#pragma prism variant SHADOWS\n#include \"a.glsl\"\n"},
                        {"a.glsl",
                         "\n#pragma prism variant QUALITY LOW MEDIUM HIGH\n"
                         "#if 0\n#pragma prism variant IGNORED\n#endif\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    ASSERT_EQ(result.stage.variantPragmas.size(), 2u);
    EXPECT_EQ(result.stage.variantPragmas[0].name, "SHADOWS");
    EXPECT_TRUE(result.stage.variantPragmas[0].values.empty());
    EXPECT_EQ(result.stage.variantPragmas[0].file, "main.frag");
    EXPECT_EQ(result.stage.variantPragmas[0].line, 1);
    EXPECT_EQ(result.stage.variantPragmas[1].name, "QUALITY");
    EXPECT_EQ(result.stage.variantPragmas[1].values, (std::vector<std::string>{"LOW", "MEDIUM", "HIGH"}));
    EXPECT_EQ(result.stage.variantPragmas[1].file, "a.glsl");
    EXPECT_EQ(result.stage.variantPragmas[1].line, 2);
    EXPECT_TRUE(lacks(result.stage.text, "prism"));
}

TEST(IncludeResolver, IdenticalVariantDeclarationsMerge) {
    MemoryReader reader{{"main.frag", "#pragma prism variant LIGHTS 1 2 4\n#include \"a.glsl\"\n"},
                        {"a.glsl", "#pragma prism variant LIGHTS 1 2 4\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok);
    ASSERT_EQ(result.stage.variantPragmas.size(), 1u);
    EXPECT_EQ(result.stage.variantPragmas[0].file, "main.frag");
}

TEST(IncludeResolver, ConflictingVariantDeclarationsNameBothPlaces) {
    MemoryReader reader{{"main.frag", "#pragma prism variant LIGHTS 1 2 4\n#include \"a.glsl\"\n"},
                        {"a.glsl", "\n#pragma prism variant LIGHTS 1 2\n"}};
    const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
    EXPECT_EQ(error.file, "a.glsl");
    EXPECT_EQ(error.line, 2);
    EXPECT_TRUE(contains(error.message, "LIGHTS"));
    EXPECT_TRUE(contains(error.message, "main.frag:1"));
    ASSERT_EQ(error.notes.size(), 1u);
    EXPECT_EQ(error.notes[0].line, 1);
}

TEST(IncludeResolver, InvalidVariantPragmasAreErrors) {
    for (const char* pragma : {"#pragma prism variant", "#pragma prism variant 9LIVES",
                               "#pragma prism variant MODE a+b", "#pragma prism variant MODE A A"}) {
        MemoryReader reader{{"main.frag", std::string("int x;\n") + pragma + "\n"}};
        const Diagnostic& error = onlyError(resolve(reader, "main.frag"));
        EXPECT_EQ(error.line, 2) << pragma;
        EXPECT_EQ(error.file, "main.frag") << pragma;
    }
}

TEST(IncludeResolver, OtherPragmasPassThrough) {
    MemoryReader reader{{"main.frag", "#pragma optimize(off)\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok);
    EXPECT_TRUE(contains(result.stage.text, "#pragma optimize(off)\n"));
}

// ---- scanModule ------------------------------------------------------------------------

TEST(ScanModule, BlanksDirectivesKeepsLinesAndReadsDescription) {
    MemoryReader reader{{"m/lighting.glsl",
                         "// Blinn-Phong lighting:\n//   diffuse and specular terms.\n"
                         "#pragma once\n#version 330 core\n#include \"math.glsl\"\n"
                         "#ifdef SHADOWS\n#include \"shadow.glsl\"\n#endif\n"
                         "vec3 light() { return vec3(1.0); }"},
                        {"m/math.glsl", "// math\n"}};
    const auto result = scanModule("m/lighting.glsl", {}, reader);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(result.diagnostics.empty());
    EXPECT_EQ(result.module.path, "m/lighting.glsl");
    EXPECT_EQ(result.module.canonical, "m/lighting.glsl");
    EXPECT_EQ(result.module.description, "Blinn-Phong lighting: diffuse and specular terms.");
    EXPECT_EQ(result.module.text,  // #version stays: composition holds it to the stage's
              "// Blinn-Phong lighting:\n//   diffuse and specular terms.\n\n#version 330 core\n\n"
              "#ifdef SHADOWS\n\n#endif\n"
              "vec3 light() { return vec3(1.0); }\n");
    EXPECT_EQ(result.module.includes, std::vector<std::string>{"m/math.glsl"});
}

TEST(ScanModule, ActiveConditionalIncludesAreListed) {
    MemoryReader reader{{"m/a.glsl", "/* A. */\n#ifdef SHADOWS\n#include <shadow.glsl>\n#endif\n"},
                        {"inc/shadow.glsl", ""}};
    ResolveOptions options;
    options.includeDirs = {"inc"};
    options.defines = {{"SHADOWS", "1"}};
    const auto result = scanModule("m/a.glsl", options, reader);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.module.includes, std::vector<std::string>{"inc/shadow.glsl"});
}

TEST(ScanModule, BlockCommentDescription) {
    MemoryReader reader{{"a.glsl", "\n/**\n * Tone mapping\n * operators.\n */\nvec3 tone(vec3 c);\n"}};
    const auto result = scanModule("a.glsl", {}, reader);
    ASSERT_TRUE(result.ok);
    EXPECT_EQ(result.module.description, "Tone mapping operators.");
}

TEST(ScanModule, MissingDescriptionIsAWarning) {
    MemoryReader reader{{"a.glsl", "vec3 tone(vec3 c);\n// late comment\n"}};
    const auto result = scanModule("a.glsl", {}, reader);
    EXPECT_TRUE(result.ok);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(result.diagnostics[0].message, "module has no leading comment saying what it provides");
}

// The catalogue turns the warning off for libraries (--warn-undocumented-modules).
TEST(ScanModule, MissingDescriptionWarningCanBeTurnedOff) {
    MemoryReader reader{{"a.glsl", "#include \"b.glsl\"\n// lygia's layout: the comment after the includes\n"},
                        {"b.glsl", "// B\n"}};
    ResolveOptions options;
    options.warnUndocumentedModule = false;
    const auto result = scanModule("a.glsl", options, reader);
    EXPECT_TRUE(result.ok);
    EXPECT_TRUE(result.diagnostics.empty()) << allMessages(result.diagnostics);
    EXPECT_EQ(result.module.description, "");
}

TEST(ScanModule, MissingIncludeIsAnError) {
    MemoryReader reader{{"a.glsl", "// A\n#include \"gone.glsl\"\n"}};
    const auto result = scanModule("a.glsl", {}, reader);
    EXPECT_FALSE(result.ok);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
    EXPECT_TRUE(contains(result.diagnostics[0].message, "gone.glsl"));
}

// ---- DiskReader ------------------------------------------------------------------------

class IncludeResolverOnDisk : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = std::filesystem::temp_directory_path() /
                ("prism_resolver_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(root_);
        std::filesystem::create_directories(root_ / "shaders");
        std::filesystem::create_directories(root_ / "modules");
    }
    void TearDown() override { std::filesystem::remove_all(root_); }

    void write(const std::string& relative, const std::string& text) {
        std::ofstream(root_ / relative, std::ios::binary) << text;
    }
    std::string path(const std::string& relative) const { return (root_ / relative).generic_string(); }

    std::filesystem::path root_;
};

TEST_F(IncludeResolverOnDisk, ResolvesFromDiskAndSymlinksShareIdentity) {
    write("shaders/main.frag", "#include \"../modules/a.glsl\"\n#include <link.glsl>\n");
    write("modules/a.glsl", "int a;\n");
    std::filesystem::create_symlink(root_ / "modules" / "a.glsl", root_ / "modules" / "link.glsl");
    ResolveOptions options;
    options.includeDirs = {path("modules")};
    const auto result = resolveStage(path("shaders/main.frag"), options, DiskReader{});
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(countOf(result.stage.text, "int a;"), 1u);
    EXPECT_EQ(result.stage.filesRead, (std::vector<std::string>{path("shaders/main.frag"), path("modules/a.glsl")}));
}

// The same file reached through two folders (an -I folder and a symlink to it) is one
// file: nothing to warn about.
TEST_F(IncludeResolverOnDisk, TheSameFileThroughTwoFoldersIsNoShadowWarning) {
    write("shaders/main.frag", "#include <a.glsl>\nvoid main() {}\n");
    write("modules/a.glsl", "int a;\n");
    std::filesystem::create_directory_symlink(root_ / "modules", root_ / "linked");
    ResolveOptions options;
    options.includeDirs = {path("modules"), path("linked")};
    const auto result = resolveStage(path("shaders/main.frag"), options, DiskReader{});
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(result.diagnostics.empty()) << allMessages(result.diagnostics);
}

TEST_F(IncludeResolverOnDisk, DirectoryIsNotAnInclude) {
    write("shaders/main.frag", "#include \"modules\"\n");
    ResolveOptions options;
    options.includeDirs = {root_.generic_string()};
    EXPECT_TRUE(contains(onlyError(resolveStage(path("shaders/main.frag"), options, DiskReader{})).message,
                         "cannot find include"));
}

// ---- glslang pins the #line semantics ----------------------------------------------------

std::string glslangInfoLog(const std::string& text) {
    static const bool initialised = glslang::InitializeProcess();
    EXPECT_TRUE(initialised);
    glslang::TShader shader(EShLangFragment);
    const char* strings[] = {text.c_str()};
    shader.setStrings(strings, 1);
    shader.parse(GetDefaultResources(), 330, ECoreProfile, false, false, EShMsgDefault);
    return shader.getInfoLog();
}

MemoryReader glslangReader(const std::string& version, const std::string& moduleBody, const std::string& mainBody) {
    return MemoryReader{{"shaders/main.frag", "#version " + version +
                                                  "\n"                            // 1
                                                  "#include \"lighting.glsl\"\n"  // 2
                                                  "out vec4 color;\n"             // 3
                                                  "void main() {\n"               // 4
                                                  "    " +
                                                  mainBody +
                                                  "\n"  // 5
                                                  "}\n"},
                        {"shaders/lighting.glsl",
                         "// Lighting helpers.\n"    // 1
                         "#include \"util.glsl\"\n"  // 2
                         "vec3 light() {\n"          // 3
                         "    " +
                             moduleBody +
                             "\n"  // 4
                             "}\n"},
                        {"shaders/util.glsl", "// Utilities.\n\nfloat unit() { return 1.0; }\n"}};
}

class IncludeResolverLineNumbers : public ::testing::TestWithParam<std::string> {};

TEST_P(IncludeResolverLineNumbers, ErrorInIncludedModuleReportedAtItsTrueLine) {
    const auto result = resolve(glslangReader(GetParam(), "return undefined_in_module;", "color = vec4(light(), 1.0);"),
                                "shaders/main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    ASSERT_EQ(result.stage.files.at(1).path, "shaders/lighting.glsl");
    const std::string log = glslangInfoLog(result.stage.text);
    EXPECT_TRUE(contains(log, "1:4: 'undefined_in_module'")) << result.stage.text;
}

TEST_P(IncludeResolverLineNumbers, ErrorInStageAfterIncludesReportedAtItsTrueLine) {
    const auto result = resolve(glslangReader(GetParam(), "return vec3(unit());", "color = vec4(undefined_in_main);"),
                                "shaders/main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    const std::string log = glslangInfoLog(result.stage.text);
    EXPECT_TRUE(contains(log, "0:5: 'undefined_in_main'")) << result.stage.text;
}

TEST_P(IncludeResolverLineNumbers, ErrorInNestedModuleReportedAtItsTrueLine) {
    MemoryReader reader = glslangReader(GetParam(), "return vec3(unit());", "color = vec4(light(), 1.0);");
    reader.add("shaders/util.glsl", "// Utilities.\n\nfloat unit() { return undefined_in_util; }\n");
    const auto result = resolve(reader, "shaders/main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    ASSERT_EQ(result.stage.files.at(2).path, "shaders/util.glsl");
    EXPECT_TRUE(contains(glslangInfoLog(result.stage.text), "2:3: 'undefined_in_util'")) << result.stage.text;
}

INSTANTIATE_TEST_SUITE_P(Versions, IncludeResolverLineNumbers, ::testing::Values("330 core", "150", "410 core"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), ' ', '_');
                             return "v" + name;
                         });

}  // namespace
}  // namespace prism::shaderc

namespace prism::shaderc {
namespace {

// ---- issue 17: guards, #pragma once, reinclude, glslang-style search ------------------

TEST(IncludeRules, PragmaOnceReentryIsNoCycle) {
    MemoryReader reader{{"main.frag", "#include \"a.glsl\"\nvoid main() {}\n"},
                        {"a.glsl", "#pragma once\n#include \"b.glsl\"\nfloat fa() { return fb(); }\n"},
                        {"b.glsl", "#include \"a.glsl\"\nfloat fb() { return 1.0; }\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_LT(result.stage.text.find("float fb()"), result.stage.text.find("float fa()"));
}

TEST(IncludeRules, GuardedReentryIsNoCycleButAnUndefinedGuardIs) {
    MemoryReader guarded{{"main.frag", "#include \"self.glsl\"\nvoid main() {}\n"},
                         {"self.glsl", "#ifndef SELF\n#define SELF\n#include \"self.glsl\"\nint s;\n#endif\n"}};
    const auto ok = resolve(guarded, "main.frag");
    ASSERT_TRUE(ok.ok) << allMessages(ok.diagnostics);
    EXPECT_EQ(countOf(ok.stage.text, "int s;"), 1u);

    // Guard-shaped, but the macro is gone again when the file re-enters: glslang would
    // recurse for ever, so it stays a cycle.
    MemoryReader undefined{{"main.frag", "#include \"self.glsl\"\n"},
                           {"self.glsl", "#ifndef SELF\n#define SELF\n#undef SELF\n#include \"self.glsl\"\n#endif\n"}};
    const Diagnostic& error = onlyError(resolve(undefined, "main.frag"));
    EXPECT_TRUE(contains(error.message, "include cycle: self.glsl -> self.glsl;"));
    EXPECT_EQ(error.line, 4);
}

TEST(IncludeRules, ReincludeOptsOutOfIncludeOnce) {
    MemoryReader reader{
        {"main.frag",
         "#define F red\n#include \"t.glsl\"\n#define F green\n#include \"t.glsl\"\n#include \"t.glsl\"\n"},
        {"t.glsl", "#pragma prism reinclude\nfloat F;\n#undef F\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(countOf(result.stage.text, "float F;"), 3u);
    EXPECT_EQ(result.stage.files.size(), 4u);
    EXPECT_TRUE(lacks(result.stage.text, "#pragma prism"));

    MemoryReader withoutPragma{{"main.frag", "#include \"t.glsl\"\n#include \"t.glsl\"\n"}, {"t.glsl", "float F;\n"}};
    EXPECT_EQ(countOf(resolve(withoutPragma, "main.frag").stage.text, "float F;"), 1u);
}

TEST(IncludeRules, SelfIncludingReincludeStopsAtTheDepthLimit) {
    MemoryReader reader{{"main.frag", "#include \"t.glsl\"\n"},
                        {"t.glsl", "#pragma prism reinclude\n#include \"t.glsl\"\n"}};
    EXPECT_TRUE(contains(onlyError(resolve(reader, "main.frag")).message, "nested more than 256 files deep"));
}

TEST(IncludeRules, QuotedSearchWalksUpTheIncludeChainBeforeIncludeDirs) {
    MemoryReader reader{{"s/main.frag", "#include \"sub/mid.glsl\"\n"},
                        {"s/sub/mid.glsl", "#include \"deeper/leaf.glsl\"\n"},
                        {"s/sub/deeper/leaf.glsl", "#include \"common.glsl\"\n"},
                        {"s/sub/common.glsl", "int from_mid_folder;\n"},
                        {"s/common.glsl", "int from_stage_folder;\n"},
                        {"inc/common.glsl", "int from_include_dir;\n"}};
    ResolveOptions options;
    options.includeDirs = {"inc"};
    auto result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "from_mid_folder"));  // the nearest folder up the chain

    MemoryReader noMid{{"s/main.frag", "#include \"sub/mid.glsl\"\n"},
                       {"s/sub/mid.glsl", "#include \"deeper/leaf.glsl\"\n"},
                       {"s/sub/deeper/leaf.glsl", "#include \"common.glsl\"\n"},
                       {"s/common.glsl", "int from_stage_folder;\n"},
                       {"inc/common.glsl", "int from_include_dir;\n"}};
    result = resolve(noMid, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "from_stage_folder"));
}

TEST(IncludeRules, LeadingSlashIsRelativeToIncludeDirsThenBaseDirNeverTheRoot) {
    MemoryReader reader{{"s/main.frag", "#include \"/lib/a.glsl\"\n"},
                        {"/lib/a.glsl", "int filesystem_root;\n"},
                        {"root/lib/a.glsl", "int under_include_dir;\n"},
                        {"base/lib/a.glsl", "int under_base_dir;\n"}};
    ResolveOptions options;
    options.includeDirs = {"root"};
    options.baseDir = "base";
    auto result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "under_include_dir"));

    options.includeDirs.clear();
    result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "under_base_dir"));

    options.baseDir.clear();
    const Diagnostic& error = onlyError(resolve(reader, "s/main.frag", options));
    EXPECT_TRUE(contains(error.message, "cannot find include \"/lib/a.glsl\""));
}

TEST(IncludeRules, DirectiveAfterMultiLineCommentIsFollowedAndTheCommentStaysClosed) {
    MemoryReader reader{{"main.frag", "/* a\n b */ #include \"x.glsl\"\nint after;\n"}, {"x.glsl", "int x;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, " b */ \n#line 1 1\nint x;\n#line 3 0\nint after;"));
}

// glslang defines GL_GOOGLE_include_directive while it preprocesses; a GL driver never
// does, and driver GLSL may not define a GL_ name, so the emitted conditionals say the
// branch glslang took.
TEST(IncludeRules, IncludeExtensionMacrosAreResolvedForTheDriver) {
    MemoryReader reader{
        {"main.frag",
         "#ifdef GL_GOOGLE_include_directive\nint a;\n#endif\n"
         "#ifndef GL_GOOGLE_include_directive\nint b;\n#endif\n"
         "#if defined(GL_GOOGLE_include_directive) && GL_GOOGLE_cpp_style_line_directive\nint c;\n#endif\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(lacks(result.stage.text, "GL_GOOGLE"));
    EXPECT_TRUE(contains(result.stage.text, "#line 1 0\n#if 1\nint a;\n#endif\n#if 0\nint b;\n#endif\n#if 1 && 1\n"));
}

// The usage example of include_search.hpp.
TEST(IncludeRules, SearchDirsHeaderExample) {
    auto dirs = includeSearchDirs(*parseIncludeTarget("\"a.glsl\""), {"s/x.frag"}, {"modules"}, "");
    ASSERT_EQ(dirs.size(), 2u);
    EXPECT_EQ(dirs[0].path, "s");
    EXPECT_EQ(dirs[0].role, "the including file's folder");
    EXPECT_EQ(dirs[1].path, "modules");
    EXPECT_TRUE(includeSearchDirs(*parseIncludeTarget("<a.glsl>"), {"s/x.frag"}, {}, "").empty());

    const auto target = *parseIncludeTarget("\"a.glsl\"");
    MemoryReader reader{{"s/a.glsl", ""}, {"modules/a.glsl", ""}};
    const auto found = findInclude(target, dirs, reader);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->display, "s/a.glsl");
    EXPECT_TRUE(contains(shadowedIncludeMessage(target, dirs, *found, reader),
                         "could mean s/a.glsl (the including file's folder) or modules/a.glsl (-I); "));
}

// ---- shadowed includes: two folders hold a file the include could mean -------------------

std::vector<Diagnostic> warningsOf(const ResolveResult& result) {
    std::vector<Diagnostic> warnings;
    for (const auto& d : result.diagnostics)
        if (d.severity == Severity::Warning) warnings.push_back(d);
    return warnings;
}

// The glslc trap: glslang (and Prism) take the ancestor's file, glslc the -I one.
TEST(ShadowedIncludes, AnAncestorFolderShadowingAnIncludeDirIsAWarningAtTheInclude) {
    MemoryReader reader{{"s/main.frag", "#include \"sub/mid.glsl\"\nvoid main() {}\n"},
                        {"s/sub/mid.glsl", "// mid\n#include \"common.glsl\"\n"},
                        {"s/common.glsl", "int ancestor;\n"},
                        {"m/common.glsl", "int library;\n"}};
    ResolveOptions options;
    options.includeDirs = {"m"};
    const auto result = resolve(reader, "s/main.frag", options);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(result.stage.text, "int ancestor;"));
    const auto warnings = warningsOf(result);
    ASSERT_EQ(warnings.size(), 1u) << allMessages(result.diagnostics);
    EXPECT_EQ(formatDiagnostic(warnings[0], ErrorFormat::Gcc),
              "s/sub/mid.glsl:2:10: warning: #include \"common.glsl\" could mean s/common.glsl (folder of "
              "s/main.frag) or m/common.glsl (-I); the first is used, but glslc (which skips the folders up the "
              "include chain) would take m/common.glsl; rename one of them, or write a path that only one folder "
              "holds (here \"../common.glsl\")\n  included from s/main.frag:1\n");
}

// Two -I libraries with the same name: the first wins, as in glslc, and the warning says so.
TEST(ShadowedIncludes, TwoIncludeDirsHoldingTheNameWarnWithoutAGlslcNote) {
    MemoryReader reader{{"s/main.frag", "#include <noise.glsl>\nvoid main() {}\n"},
                        {"a/noise.glsl", "int a;\n"},
                        {"b/noise.glsl", "int b;\n"}};
    ResolveOptions options;
    options.includeDirs = {"a", "b"};
    const auto result = resolve(reader, "s/main.frag", options);
    const auto warnings = warningsOf(result);
    ASSERT_EQ(warnings.size(), 1u) << allMessages(result.diagnostics);
    EXPECT_TRUE(contains(warnings[0].message, "<noise.glsl> could mean a/noise.glsl (-I) or b/noise.glsl (-I)"));
    EXPECT_TRUE(lacks(warnings[0].message, "glslc"));
    EXPECT_EQ(warnings[0].line, 1);
    EXPECT_EQ(warnings[0].column, 10);
}

// A module scanned on its own says nothing: the stages that include it warn, with their chain.
TEST(ShadowedIncludes, AModuleScanLeavesTheWarningToTheStages) {
    MemoryReader reader{{"m/a.glsl", "// A\n#ifndef X\n#include \"common.glsl\"\n#endif\n"},  // glslang decides
                        {"m/common.glsl", "// here\n"},
                        {"n/common.glsl", "// there\n"}};
    ResolveOptions options;
    options.includeDirs = {"m", "n"};
    const auto result = scanModule("m/a.glsl", options, reader);
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_TRUE(result.diagnostics.empty()) << allMessages(result.diagnostics);
}

// glslang must know the version before it starts; a #version met first in a module
// makes the stage run again with it, so __VERSION__ and the profile macros agree.
TEST(IncludeRules, VersionFromAModuleDrivesPredefinedMacros) {
    MemoryReader reader{{"main.frag",
                         "#include \"v.glsl\"\n#if __VERSION__ == 450 && GL_ARB_gpu_shader5\n"
                         "#include \"yes.glsl\"\n#endif\nvoid main() {}\n"},
                        {"v.glsl", "#version 450 core\n"},
                        {"yes.glsl", "int modern;\n"}};
    const auto result = resolve(reader, "main.frag");
    ASSERT_TRUE(result.ok) << allMessages(result.diagnostics);
    EXPECT_EQ(result.stage.versionDirective, "#version 450 core");
    EXPECT_TRUE(contains(result.stage.text, "int modern;"));
}

// glslang_preprocessor.hpp's entry point on its own (the one a fuzzer drives): which
// files glslang entered, from which line, and which probed directives it reached.
TEST(GlslangPreprocessor, RecordsWhatGlslangIncludes) {
    MemoryReader reader{{"s/a.frag",
                         "#version 330 core\n#define TWICE(x) ((x) * 2)\n#if TWICE(2) == 4\n"
                         "#include \"b.glsl\"\n#else\n#include \"c.glsl\"\n#endif\n#pragma prism variant X\n"},
                        {"s/b.glsl", "#include \"c.glsl\"\n"},
                        {"s/c.glsl", "int c;\n"}};
    const auto run = preprocessWithGlslang("s/a.frag", {}, GlslVersion{330, "core"}, reader);
    ASSERT_TRUE(run.ok) << allMessages(run.diagnostics);
    ASSERT_EQ(run.files.size(), 3u);
    EXPECT_EQ(run.files[0].includes, (std::map<int, std::uint32_t>{{4, 1}}));  // line 6 is inactive
    EXPECT_EQ(run.files[1].display, "s/b.glsl");
    EXPECT_EQ(run.files[1].includes, (std::map<int, std::uint32_t>{{1, 2}}));
    EXPECT_EQ(run.files[2].chain, (std::vector<IncludeSite>{{"s/b.glsl", 1}, {"s/a.frag", 4}}));
    EXPECT_EQ(run.files[0].reached, (std::set<int>{1, 4, 8}));  // #version, #include, #pragma prism
    ASSERT_EQ(run.files[0].found.size(), 1u);
    EXPECT_EQ(run.files[0].found[0].display, "s/b.glsl");
}

}  // namespace
}  // namespace prism::shaderc
