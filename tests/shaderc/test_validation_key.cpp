// Unit tests of the validation key (validation_key.hpp): equal for texts that are one
// token stream for glslang, different as soon as a token can differ.
#include <gtest/gtest.h>

#include <string>

#include "source_reader.hpp"
#include "validation_key.hpp"

namespace prism::shaderc {
namespace {

const DefineList kDefines{{"FOG", "1"}, {"UNUSED", "2"}};

ResolvedStage stageOf(const std::string& body, const DefineList& defines = kDefines) {
    ResolvedStage stage;
    stage.versionDirective = "#version 330 core";
    stage.text = stage.versionDirective + "\n";
    for (const auto& [name, value] : defines) stage.text += "#define " + name + " " + value + "\n";
    stage.text += body;
    stage.filesRead = {"a.frag"};
    return stage;
}

std::string keyOf(const std::string& body, const std::string& file, const DefineList& defines = kDefines) {
    const MemoryReader reader{{"a.frag", file}};
    return validationKey(stageOf(body, defines), defines, reader);
}

const std::string kFile =
    "#pragma prism variant UNUSED\n// UNUSED in a comment\nout vec4 o;\nvoid main() { o = vec4(FOG); }\n";
const std::string kBody = "#line 1 0\n\n\nout vec4 o;\nvoid main() { o = vec4(FOG); }\n";

TEST(ValidationKey, CommentsLayoutAndLineMarkersDoNotCount) {
    const std::string moved =
        "#line 7 0\n// a comment\n  out  vec4   o;\n\n#line 12 0\nvoid main() { o = vec4(FOG); /* x */ }\n";
    EXPECT_EQ(keyOf(kBody, kFile), keyOf(moved, kFile));
}

TEST(ValidationKey, CodeCounts) {
    EXPECT_NE(keyOf(kBody, kFile), keyOf("#line 1 0\nout vec4 o;\nvoid main() { o = vec4(FOG) * 2.0; }\n", kFile));
}

// UNUSED appears only in a #pragma line and a comment: no token of the stage is it.
TEST(ValidationKey, OnlyDefinesTheFilesMeetCount) {
    EXPECT_EQ(keyOf(kBody, kFile), keyOf(kBody, kFile, {{"FOG", "1"}, {"UNUSED", "3"}}));
    EXPECT_NE(keyOf(kBody, kFile), keyOf(kBody, kFile, {{"FOG", "0"}, {"UNUSED", "2"}}));
    // A macro's value can name another: then it counts.
    EXPECT_NE(keyOf(kBody, kFile, {{"FOG", "UNUSED"}, {"UNUSED", "2"}}),
              keyOf(kBody, kFile, {{"FOG", "UNUSED"}, {"UNUSED", "3"}}));
    // Token pasting can build any name: every define counts.
    const std::string pasting = kFile + "#define CAT(a, b) a##b\n";
    EXPECT_NE(keyOf(kBody, pasting), keyOf(kBody, pasting, {{"FOG", "1"}, {"UNUSED", "3"}}));
}

// __LINE__ gives line numbers to the code, which the markers set: the text counts whole.
TEST(ValidationKey, LineMacroMakesLayoutCount) {
    const std::string file = "int l = __LINE__;\n";
    EXPECT_NE(keyOf("#line 1 0\nint l = __LINE__;\n", file), keyOf("#line 2 0\nint l = __LINE__;\n", file));
    EXPECT_EQ(keyOf("#line 1 0\nint l = __LINE__;\n", file), keyOf("#line 1 0\nint l = __LINE__;\n", file));
}

// Only the flattener's own markers (`#line N` or `#line N S`) are left out: a malformed
// #line is an error glslang must see.
TEST(ValidationKey, OtherLineDirectivesCount) {
    EXPECT_NE(keyOf(kBody, kFile),
              keyOf("#line 1 0\n#line oops\n\nout vec4 o;\nvoid main() { o = vec4(FOG); }\n", kFile));
    EXPECT_NE(keyOf(kBody, kFile), keyOf("#line 1 0 3\n\n\nout vec4 o;\nvoid main() { o = vec4(FOG); }\n", kFile));
}

TEST(ValidationKey, VersionCounts) {
    const MemoryReader reader{{"a.frag", kFile}};
    ResolvedStage other = stageOf(kBody);
    other.versionDirective = "#version 450 core";
    EXPECT_NE(validationKey(stageOf(kBody), kDefines, reader), validationKey(other, kDefines, reader));
}

// The basis of one run serves every variant that shares it.
TEST(ValidationKey, BasisGivesTheSameKey) {
    const MemoryReader reader{{"a.frag", kFile}};
    const auto basis = validationKeyBasis(stageOf(kBody), kDefines.size(), {"FOG", "UNUSED"}, reader);
    EXPECT_EQ(validationKey(stageOf(kBody), kDefines, basis), validationKey(stageOf(kBody), kDefines, reader));
}

// Hostile stages: no text at all, fewer lines than defines, a file that cannot be read
// (every define then counts), 1 MB of blanks.
TEST(ValidationKey, HostileStages) {
    const MemoryReader reader{{"a.frag", kFile}};
    ResolvedStage empty;
    empty.filesRead = {"missing.frag"};
    EXPECT_EQ(validationKey(empty, kDefines, reader).size(), 32u);
    EXPECT_NE(validationKey(empty, kDefines, reader), validationKey(empty, {{"FOG", "1"}, {"UNUSED", "3"}}, reader));
    ResolvedStage shortText = stageOf("", {});
    EXPECT_EQ(validationKey(shortText, kDefines, reader).size(), 32u);
    EXPECT_EQ(keyOf(kBody + std::string(1 << 20, ' ') + "\n", kFile), keyOf(kBody, kFile));
}

}  // namespace
}  // namespace prism::shaderc
