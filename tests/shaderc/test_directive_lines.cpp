// Unit tests of the lexical preprocessor pieces: logical lines, directives and #version.
#include <gtest/gtest.h>

#include <string>

#include "directive_lines.hpp"

namespace prism::shaderc {
namespace {

// ---- logical lines and directives ------------------------------------------------------

TEST(LogicalLines, EmptyTextHasNoLines) {
    EXPECT_TRUE(splitLogicalLines("").empty());
}

TEST(LogicalLines, CrlfAndMissingTrailingNewline) {
    const auto lines = splitLogicalLines("a\r\nb\r\n\r\nc");
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].physical.front(), "a");
    EXPECT_EQ(lines[1].physical.front(), "b");
    EXPECT_EQ(lines[2].physical.front(), "");
    EXPECT_EQ(lines[3].physical.front(), "c");
    EXPECT_EQ(lines[3].firstLine, 4);
}

TEST(LogicalLines, ContinuationJoinsPhysicalLines) {
    const auto lines = splitLogicalLines("#define A 1 + \\\n  2\nnext\n");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].physical.size(), 2u);
    EXPECT_EQ(lines[0].code, "#define A 1 +   2");
    EXPECT_EQ(lines[1].firstLine, 3);
}

TEST(LogicalLines, BlockCommentSpansLines) {
    const auto lines = splitLogicalLines("a /* start\n#include \"x\"\nend */ b\nc\n");
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_FALSE(lines[0].startsInComment);
    EXPECT_TRUE(lines[1].startsInComment);
    EXPECT_TRUE(lines[2].startsInComment);
    EXPECT_FALSE(lines[3].startsInComment);
    EXPECT_EQ(std::string(trim(lines[1].code)), "");
    EXPECT_EQ(std::string(trim(lines[2].code)), "b");
}

TEST(LogicalLines, LineCommentContinuedByBackslashCoversNextLine) {
    const auto lines = splitLogicalLines("// comment \\\n#include \"x\"\n");
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_FALSE(parseDirective(lines[0]).has_value());
}

TEST(PreprocessorDirectives, RecognisesSpacedDirectives) {
    const auto lines = splitLogicalLines("  #  define   X 1 // note\n");
    const auto directive = parseDirective(lines.at(0));
    ASSERT_TRUE(directive);
    EXPECT_EQ(directive->name, "define");
    EXPECT_EQ(directive->argument, "X 1");
}

TEST(PreprocessorDirectives, CommentBeforeHashOnSameLineStillADirective) {
    const auto directive = parseDirective(splitLogicalLines("/* c */ #ifdef A\n").at(0));
    ASSERT_TRUE(directive);
    EXPECT_EQ(directive->name, "ifdef");
}

TEST(PreprocessorDirectives, DoubleSlashInsideIncludeQuotesIsNotAComment) {
    const auto directive = parseDirective(splitLogicalLines("#include \"a//b.glsl\"\n").at(0));
    ASSERT_TRUE(directive);
    EXPECT_EQ(directive->argument, "\"a//b.glsl\"");
}

TEST(PreprocessorDirectives, CodeLineIsNotADirective) {
    EXPECT_FALSE(parseDirective(splitLogicalLines("float x; // #include \"y\"\n").at(0)));
}

TEST(PreprocessorDirectives, DirectiveAfterAMultiLineCommentIsADirective) {
    // glslang reads "/* ... */ #include" on the comment's last line as a directive.
    const auto lines = splitLogicalLines("/* a\n b */ #include \"x.glsl\"\nfloat y;\n");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_TRUE(lines[0].endsInComment);
    EXPECT_TRUE(lines[1].startsInComment);
    const auto directive = parseDirective(lines[1]);
    ASSERT_TRUE(directive);
    EXPECT_EQ(directive->name, "include");
    EXPECT_FALSE(lines[1].endsInComment);
}

// ---- versions --------------------------------------------------------------------------

TEST(GlslVersionDirective, ParsesAndCompares) {
    const auto core = parseVersionArgument("330 core");
    const auto plain = parseVersionArgument("330");
    ASSERT_TRUE(core && plain);
    EXPECT_TRUE(core->sameAs(*plain));
    EXPECT_EQ(plain->directive(), "#version 330");
    EXPECT_FALSE(core->sameAs(*parseVersionArgument("330 compatibility")));
    EXPECT_FALSE(core->sameAs(*parseVersionArgument("450 core")));
    EXPECT_FALSE(parseVersionArgument("abc"));
    EXPECT_FALSE(parseVersionArgument("330 banana"));
    EXPECT_FALSE(parseVersionArgument(""));
    EXPECT_EQ(parseVersionDirective("#version 150 // comment")->number, 150);
}

}  // namespace
}  // namespace prism::shaderc
