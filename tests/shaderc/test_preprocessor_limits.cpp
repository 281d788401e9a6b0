// The stated limits of prism-shaderc's preprocessing (issue 17): each of the inputs
// that crashed or stalled the resolver (for minutes) ends with a clear error, and inputs
// just inside the limits still work. The time bound is a hang guard, far above the
// ~0.1 s these take in a Release build, so that ASan on a loaded CI core stays under it;
// it is no speed measurement.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "include_resolver.hpp"
#include "preprocessor_limits.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {
namespace {

struct Timed {
    ResolveResult result;
    double seconds = 0;
};

Timed resolveTimed(const std::string& stage) {
    MemoryReader reader{{"main.frag", stage}};
    const auto start = std::chrono::steady_clock::now();
    Timed t{resolveStage("main.frag", {}, reader), 0};
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

std::string messages(const ResolveResult& r) {
    std::string text;
    for (const auto& d : r.diagnostics) text += formatDiagnostic(d, ErrorFormat::Gcc);
    return text;
}

// `levels` macros, each twice the one before: 2^levels tokens.
std::string doublingChain(int levels) {
    std::string text = "#define M0 1\n";
    for (int i = 1; i <= levels; ++i)
        text += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " + M" + std::to_string(i - 1) + "\n";
    return text;
}

void expectClearErrorFast(const Timed& t, const std::string& message, int line) {
    EXPECT_FALSE(t.result.ok);
    EXPECT_LT(t.seconds, 20.0) << "the stated limit is a clear error, not a stall";
    ASSERT_FALSE(t.result.diagnostics.empty());
    const auto& first = t.result.diagnostics.front();
    EXPECT_NE(first.message.find(message), std::string::npos) << messages(t.result);
    EXPECT_EQ(first.file, "main.frag");
    EXPECT_EQ(first.line, line);
}

TEST(PreprocessorLimits, HundredThousandNestedParenthesesInIf) {
    const std::string deep = std::string(100000, '(') + "1" + std::string(100000, ')');
    expectClearErrorFast(resolveTimed("#version 330 core\n#if " + deep + "\n#endif\nvoid main() {}\n"),
                         "#if expression has more than 10,000 tokens after macro expansion (limit)", 2);
}

TEST(PreprocessorLimits, TwoHundredThousandNotsInIf) {
    expectClearErrorFast(resolveTimed("#version 330 core\n#if " + std::string(200000, '!') + "1\n#endif\n"),
                         "#if expression has more than 10,000 tokens", 2);
}

TEST(PreprocessorLimits, DoublingMacroChainInIf) {
    expectClearErrorFast(resolveTimed(doublingChain(22) + "#if M22 > 0\n#endif\nvoid main() {}\n"),
                         "#if expression has more than 10,000 tokens after macro expansion", 24);
}

TEST(PreprocessorLimits, DoublingMacroChainInCode) {
    expectClearErrorFast(resolveTimed(doublingChain(22) + "float x = float(M22);\nvoid main() {}\n"),
                         "the macros on this line expand to more than 1,000,000 tokens (limit)", 24);
}

// The chain is defined in an include and used after it, in the includer and in the file
// that includes the includer: those lines were checked before the include was read, so
// they are checked again once it is (and blanked before glslang reaches them).
TEST(PreprocessorLimits, DoublingMacroChainDefinedInAnInclude) {
    const auto start = std::chrono::steady_clock::now();
    MemoryReader reader{
        {"main.frag", "#version 330 core\n#include \"mid.glsl\"\nfloat y = float(M22);\nvoid main() {}\n"},
        {"mid.glsl", "#include \"chain.glsl\"\nfloat x = float(M22);\n"},
        {"chain.glsl", doublingChain(22)}};
    const auto result = resolveStage("main.frag", {}, reader);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(result.ok);
    EXPECT_LT(seconds, 20.0) << "the stated limit is a clear error, not a stall";
    std::vector<std::string> places;
    for (const auto& d : result.diagnostics)
        if (d.message.find("expand to more than 1,000,000 tokens (limit)") != std::string::npos)
            places.push_back(d.file + ":" + std::to_string(d.line));
    EXPECT_EQ(places, (std::vector<std::string>{"main.frag:3", "mid.glsl:2"})) << messages(result);
}

TEST(PreprocessorLimits, NestedMacroCallsAreBounded) {
    std::string calls = "X";
    for (int i = 0; i < 300; ++i) calls = "TWICE(" + calls + ")";
    expectClearErrorFast(resolveTimed("#define TWICE(a) a a\n#if " + calls + "\n#endif\n"),
                         "macro expansion nested more than 256 levels deep (limit)", 2);
}

TEST(PreprocessorLimits, GlslangsIfNestingLimitIsAClearError) {
    std::string text = "#version 330 core\n";
    for (int i = 0; i < 70; ++i) text += "#if 1\n";
    for (int i = 0; i < 70; ++i) text += "#endif\n";
    const auto t = resolveTimed(text + "void main() {}\n");
    expectClearErrorFast(t, "maximum nesting depth exceeded", 2 + 65);  // glslang's own limit: 65 groups
}

TEST(PreprocessorLimits, InsideTheLimitsGlslangDecides) {
    const auto chain = resolveTimed(doublingChain(12) + "#if M12 == 4096\nint taken;\n#endif\nvoid main() {}\n");
    EXPECT_TRUE(chain.result.ok) << messages(chain.result);
    const std::string parens = std::string(2000, '(') + "1" + std::string(2000, ')');
    const auto deep = resolveTimed("#if " + parens + "\nint taken;\n#endif\nvoid main() {}\n");
    EXPECT_TRUE(deep.result.ok) << messages(deep.result);
    std::string nested = "#version 330 core\n";
    for (int i = 0; i < 60; ++i) nested += "#if 1\n";
    for (int i = 0; i < 60; ++i) nested += "#endif\n";
    EXPECT_TRUE(resolveTimed(nested).result.ok);
}

TEST(PreprocessorLimits, SizeBoundCountsExpandedTokensExactlyAtTheEdge) {
    PreprocessorLimits limits;
    limits.maxConditionTokens = 9;
    MacroSizeTable macros;
    const auto lines = splitLogicalLines(
        "#define A x x\n#define F(p) p p p\n#if A A A\n#endif\n#if A A A A A\n#endif\n#if F(A) 1 1 1\n#endif\n"
        "#if F(A) 1 1 1 1\n#endif\n");
    const auto problems = checkPreprocessorLimits("f.glsl", lines, macros, limits);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0].line, 5);  // 10 tokens
    EXPECT_EQ(problems[1].line, 9);  // F(A) is 6, plus 4
}

TEST(PreprocessorLimits, ConditionalsMustBalanceInEachFile) {
    const auto problems =
        checkConditionalStructure("f.glsl", splitLogicalLines("#if A\n#else\n#elif B\n#endif\n#endif\n#ifdef C\n"));
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_EQ(problems[0].message, "#elif after #else (the #else is at line 2)");
    EXPECT_EQ(problems[1].message, "#endif without #if");
    EXPECT_EQ(problems[2].message, "unterminated #ifdef: no matching #endif before the end of the file");
    EXPECT_EQ(problems[2].line, 6);
}

}  // namespace
}  // namespace prism::shaderc
