// Unit tests of the include resolver's preprocessor pieces: logical lines, directives,
// the #if expression evaluator, the conditional stack and version macros.
#include <gtest/gtest.h>

#include <string>

#include "preprocessor_conditions.hpp"

namespace prism::shaderc {
namespace {

std::int64_t valueOf(std::string_view expression, const MacroTable& macros = {}) {
    const ConditionValue result = evaluateCondition(expression, macros);
    EXPECT_TRUE(result.ok()) << expression << ": " << result.error;
    return result.value;
}

std::string errorOf(std::string_view expression, const MacroTable& macros = {}) {
    const ConditionValue result = evaluateCondition(expression, macros);
    EXPECT_FALSE(result.ok()) << expression << " evaluated to " << result.value;
    return result.error;
}

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

// ---- expressions -----------------------------------------------------------------------

TEST(ConditionExpression, ArithmeticPrecedence) {
    EXPECT_EQ(valueOf("1 + 2 * 3"), 7);
    EXPECT_EQ(valueOf("(1 + 2) * 3"), 9);
    EXPECT_EQ(valueOf("1 << 2 + 1"), 8);
    EXPECT_EQ(valueOf("10 - 4 - 3"), 3);  // left associative
    EXPECT_EQ(valueOf("100 / 10 / 5"), 2);
    EXPECT_EQ(valueOf("10 % 3"), 1);
    EXPECT_EQ(valueOf("-7 / 2"), -3);
}

TEST(ConditionExpression, BitwiseAndComparisonPrecedence) {
    EXPECT_EQ(valueOf("3 & 5 == 5"), 1);  // 3 & (5 == 5)
    EXPECT_EQ(valueOf("6 & 3 == 2"), 0);  // 6 & (3 == 2)
    EXPECT_EQ(valueOf("1 | 2 ^ 3 & 1"), 3);
    EXPECT_EQ(valueOf("1 < 2 == 1"), 1);
    EXPECT_EQ(valueOf("2 >= 3 || 4 <= 4 && 1 != 0"), 1);
    EXPECT_EQ(valueOf("0 || 0 && 1"), 0);
}

TEST(ConditionExpression, UnaryOperators) {
    EXPECT_EQ(valueOf("!0"), 1);
    EXPECT_EQ(valueOf("!5"), 0);
    EXPECT_EQ(valueOf("~0"), -1);
    EXPECT_EQ(valueOf("-(2 + 3)"), -5);
    EXPECT_EQ(valueOf("+4"), 4);
    EXPECT_EQ(valueOf("- -1"), 1);
}

TEST(ConditionExpression, TernaryIsRightAssociative) {
    EXPECT_EQ(valueOf("1 ? 2 : 3"), 2);
    EXPECT_EQ(valueOf("0 ? 2 : 0 ? 4 : 5"), 5);
    EXPECT_EQ(valueOf("0 ? 2 : 1 ? 4 : 5"), 4);
}

TEST(ConditionExpression, IntegerLiterals) {
    EXPECT_EQ(valueOf("0x1F"), 31);
    EXPECT_EQ(valueOf("0XfF"), 255);
    EXPECT_EQ(valueOf("010"), 8);
    EXPECT_EQ(valueOf("0"), 0);
    EXPECT_EQ(valueOf("5u"), 5);
    EXPECT_NE(errorOf("1.5").find("invalid integer literal '1.5'"), std::string::npos);
    EXPECT_NE(errorOf("09").find("invalid integer literal"), std::string::npos);
}

TEST(ConditionExpression, DefinedInBothForms) {
    MacroTable macros;
    macros.define("FOO", "");
    EXPECT_EQ(valueOf("defined FOO", macros), 1);
    EXPECT_EQ(valueOf("defined(FOO)", macros), 1);
    EXPECT_EQ(valueOf("defined ( FOO ) && !defined BAR", macros), 1);
    EXPECT_EQ(valueOf("defined(BAR)", macros), 0);
    EXPECT_NE(errorOf("defined", macros).find("macro name"), std::string::npos);
    EXPECT_NE(errorOf("defined(FOO", macros).find("missing ')'"), std::string::npos);
}

TEST(ConditionExpression, UndefinedIdentifiersAreZero) {
    EXPECT_EQ(valueOf("UNKNOWN"), 0);
    EXPECT_EQ(valueOf("UNKNOWN + 3"), 3);
    EXPECT_EQ(valueOf("UNKNOWN == 0"), 1);
}

TEST(ConditionExpression, MacrosExpandRecursivelyAsTokens) {
    MacroTable macros;
    macros.define("QUALITY", "MEDIUM");
    macros.define("MEDIUM", "2");
    macros.define("SUM", "1 + 2");
    EXPECT_EQ(valueOf("QUALITY == 2", macros), 1);
    EXPECT_EQ(valueOf("SUM * 3", macros), 7);  // token splicing, like C: 1 + 2 * 3
}

TEST(ConditionExpression, SelfReferenceDoesNotLoop) {
    MacroTable macros;
    macros.define("X", "X + 1");
    macros.define("A", "B");
    macros.define("B", "A");
    EXPECT_EQ(valueOf("X", macros), 1);  // X + 1 with the inner X undefined
    EXPECT_EQ(valueOf("A", macros), 0);
}

TEST(ConditionExpression, DeepExpansionChainIsAnError) {
    MacroTable macros;
    for (int i = 0; i < 100; ++i) macros.define("M" + std::to_string(i), "M" + std::to_string(i + 1));
    EXPECT_NE(errorOf("M0", macros).find("nested"), std::string::npos);
}

TEST(ConditionExpression, FunctionLikeMacroIsAnError) {
    MacroTable macros;
    EXPECT_EQ(macros.defineFromDirective("F(x) ((x) + 1)"), "");
    ASSERT_TRUE(macros.find("F"));
    EXPECT_TRUE(macros.find("F")->functionLike);
    EXPECT_EQ(valueOf("defined F", macros), 1);
    EXPECT_NE(errorOf("F(1)", macros).find("function-like macro 'F'"), std::string::npos);
}

TEST(ConditionExpression, DivisionByZeroIsAClearError) {
    EXPECT_EQ(errorOf("1 / 0"), "division by zero");
    EXPECT_EQ(errorOf("1 % (2 - 2)"), "division by zero");
}

TEST(ConditionExpression, ShortCircuitSkipsDivisionByZero) {
    EXPECT_EQ(valueOf("0 && 1 / 0"), 0);
    EXPECT_EQ(valueOf("1 || 1 / 0"), 1);
    EXPECT_EQ(valueOf("1 ? 2 : 1 / 0"), 2);
    EXPECT_EQ(valueOf("0 ? 1 / 0 : 3"), 3);
}

TEST(ConditionExpression, SyntaxErrors) {
    EXPECT_EQ(errorOf(""), "missing expression");
    EXPECT_NE(errorOf("(1").find("expected ')'"), std::string::npos);
    EXPECT_NE(errorOf("1 +").find("too early"), std::string::npos);
    EXPECT_NE(errorOf("1 2").find("unexpected '2'"), std::string::npos);
    EXPECT_NE(errorOf("1 @ 2").find("unexpected character '@'"), std::string::npos);
    EXPECT_NE(errorOf("1 ? 2").find("expected ':'"), std::string::npos);
}

TEST(ConditionExpression, OverflowWrapsInsteadOfCrashing) {
    EXPECT_TRUE(evaluateCondition("0x7fffffffffffffff + 1", {}).ok());
    EXPECT_TRUE(evaluateCondition("(-0x7fffffffffffffff - 1) / -1", {}).ok());
    EXPECT_TRUE(evaluateCondition("1 << 200", {}).ok());
}

// ---- the conditional stack -------------------------------------------------------------

struct StackDriver {
    ConditionalStack stack;
    MacroTable macros;
    int line = 0;

    std::string apply(const std::string& text) {
        const auto directive = parseDirective(splitLogicalLines(text).at(0));
        EXPECT_TRUE(directive) << text;
        return stack.apply(*directive, ++line, macros);
    }
};

TEST(ConditionalStack, IfElseEndif) {
    StackDriver d;
    EXPECT_TRUE(d.stack.active());
    EXPECT_EQ(d.apply("#if 0"), "");
    EXPECT_FALSE(d.stack.active());
    EXPECT_EQ(d.apply("#else"), "");
    EXPECT_TRUE(d.stack.active());
    EXPECT_EQ(d.apply("#endif"), "");
    EXPECT_TRUE(d.stack.active());
    EXPECT_FALSE(d.stack.innermostOpen());
}

TEST(ConditionalStack, ElifChainTakesFirstTrueBranchOnly) {
    StackDriver d;
    d.macros.define("LEVEL", "2");
    d.apply("#if LEVEL == 1");
    EXPECT_FALSE(d.stack.active());
    d.apply("#elif LEVEL == 2");
    EXPECT_TRUE(d.stack.active());
    d.apply("#elif LEVEL >= 2");
    EXPECT_FALSE(d.stack.active());
    d.apply("#else");
    EXPECT_FALSE(d.stack.active());
    d.apply("#endif");
    EXPECT_TRUE(d.stack.active());
}

TEST(ConditionalStack, IfdefAndIfndef) {
    StackDriver d;
    d.macros.define("HAVE", "");
    d.apply("#ifdef HAVE");
    EXPECT_TRUE(d.stack.active());
    d.apply("#ifndef HAVE");
    EXPECT_FALSE(d.stack.active());
    d.apply("#endif");
    d.apply("#endif");
    d.apply("#ifndef MISSING");
    EXPECT_TRUE(d.stack.active());
    EXPECT_NE(d.apply("#ifdef").find("needs a macro name"), std::string::npos);
}

TEST(ConditionalStack, InactiveParentIsNeverEvaluated) {
    StackDriver d;
    d.apply("#if 0");
    EXPECT_EQ(d.apply("#if 1 / 0"), "");  // not evaluated: no error
    EXPECT_FALSE(d.stack.active());
    EXPECT_EQ(d.apply("#else"), "");
    EXPECT_FALSE(d.stack.active());  // parent is still inactive
    d.apply("#endif");
    EXPECT_EQ(d.apply("#elif 1"), "");
    EXPECT_TRUE(d.stack.active());
}

TEST(ConditionalStack, ElifAfterTakenBranchIsNotEvaluated) {
    StackDriver d;
    d.apply("#if 1");
    EXPECT_EQ(d.apply("#elif 1 / 0"), "");
    EXPECT_FALSE(d.stack.active());
}

TEST(ConditionalStack, BadExpressionDisablesTheWholeGroup) {
    StackDriver d;
    EXPECT_EQ(d.apply("#if 1 / 0"), "#if: division by zero");
    EXPECT_FALSE(d.stack.active());
    d.apply("#else");
    EXPECT_FALSE(d.stack.active());
}

TEST(ConditionalStack, UnbalancedDirectivesAreErrors) {
    StackDriver d;
    EXPECT_EQ(d.apply("#endif"), "#endif without #if");
    EXPECT_EQ(d.apply("#else"), "#else without #if");
    EXPECT_EQ(d.apply("#elif 1"), "#elif without #if");
    d.apply("#if 1");  // line 4
    d.apply("#else");  // line 5
    EXPECT_NE(d.apply("#else").find("#else after #else (the first #else is at line 5)"), std::string::npos);
    EXPECT_NE(d.apply("#elif 1").find("#elif after #else"), std::string::npos);
}

TEST(ConditionalStack, ReportsInnermostOpenGroup) {
    StackDriver d;
    d.apply("#if 1");
    d.apply("#ifdef X");
    const auto open = d.stack.innermostOpen();
    ASSERT_TRUE(open);
    EXPECT_EQ(open->directive, "ifdef");
    EXPECT_EQ(open->line, 2);
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

TEST(GlslVersionDirective, PredefinedMacros) {
    MacroTable macros;
    predefineVersionMacros(macros, *parseVersionArgument("330"));
    EXPECT_EQ(valueOf("__VERSION__ == 330 && GL_core_profile == 1 && !defined GL_ES", macros), 1);
    predefineVersionMacros(macros, *parseVersionArgument("150 compatibility"));
    EXPECT_EQ(valueOf("__VERSION__ == 150 && defined GL_compatibility_profile && !defined GL_core_profile", macros), 1);
    predefineVersionMacros(macros, *parseVersionArgument("120"));
    EXPECT_EQ(valueOf("defined GL_core_profile", macros), 0);
    predefineVersionMacros(macros, *parseVersionArgument("300 es"));
    EXPECT_EQ(valueOf("GL_ES", macros), 1);
}

}  // namespace
}  // namespace prism::shaderc
