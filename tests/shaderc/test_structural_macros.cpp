// Unit tests of the lexical analysis behind variant sharing (structural_macros.hpp):
// which macros can change the files a run enters and the directives it reaches.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "structural_macros.hpp"

namespace prism::shaderc {
namespace {

std::set<std::string> decisive(std::initializer_list<std::string_view> texts) {
    const auto found = structuralMacros(std::vector<std::string_view>(texts));
    EXPECT_TRUE(found.has_value());
    return found ? found->decisive : std::set<std::string>{"<none>"};
}

using Names = std::set<std::string>;

TEST(StructuralMacros, AMacroOnlyInCodeOrAroundCodeIsNot) {
    EXPECT_EQ(decisive({"float f = BLINN;\n#if FOG\nvec3 c = fogged(c);\n#else\nvec3 c = c;\n#endif\n"}), Names{});
}

TEST(StructuralMacros, EveryConditionOfAGroupAroundAnIncludeIs) {
    EXPECT_EQ(decisive({"#if A > 1\nfloat a;\n#elif defined(B)\n#include \"x.glsl\"\n#else\n#endif\n"}),
              (Names{"A", "B", "defined"}));
    // Nested groups: the outer condition too.
    EXPECT_EQ(decisive({"#ifdef OUTER\n#if INNER\n#version 330 core\n#endif\n#endif\n"}), (Names{"OUTER", "INNER"}));
}

// A #define of a structural macro under a condition makes that condition structural,
// and so do the macros in its body, in any file: closed over every file read.
TEST(StructuralMacros, DefinesOfStructuralMacrosCarryItOn) {
    EXPECT_EQ(decisive({"#if FOG\n#define WANT_FOG SHARP\n#endif\n",
                        "#ifdef WANT_FOG\n#include \"fog.glsl\"\n#endif\n#if UNRELATED\n#define OTHER 1\n#endif\n"}),
              (Names{"FOG", "WANT_FOG", "SHARP"}));
    // An #undef counts as a definition.
    EXPECT_EQ(decisive({"#if Q\n#undef G\n#endif\n#ifndef G\n#error no G\n#endif\n"}), (Names{"Q", "G"}));
}

// glslang never expands the words of #pragma, #extension, #version and #error lines:
// only the groups around them count. #include and #line lines are expanded.
TEST(StructuralMacros, WordsOfUnexpandedDirectivesAreNot) {
    EXPECT_EQ(decisive({"#pragma prism variant FOG\n#extension GL_ARB_foo : enable\n#error FOG\n"}), Names{});
    EXPECT_EQ(decisive({"#if G\n#pragma prism variant V\n#endif\n"}), Names{"G"});
    EXPECT_EQ(decisive({"#line LINE_NUMBER\n#include INCLUDE_NAME\n"}), (Names{"LINE_NUMBER", "INCLUDE_NAME"}));
}

TEST(StructuralMacros, CommentsAndNumberSuffixesAreNotNames) {
    EXPECT_EQ(decisive({"#if 1u /* FOG */ // BLINN\n#include \"x.glsl\"\n#endif\n"}), Names{});
}

TEST(StructuralMacros, DefinedNamesAreListed) {
    const auto found = structuralMacros({"#define ONE 1\n#if X\n#define TWO() 2\n#endif\n"});
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->defined, (Names{"ONE", "TWO"}));
}

TEST(StructuralMacros, PastingOrUnbalancedGroupsCannotBeTold) {
    EXPECT_FALSE(structuralMacros({"#define CAT(a, b) a##b\n"}).has_value());
    EXPECT_FALSE(structuralMacros({"#if A\n#include \"x.glsl\"\n"}).has_value());  // no #endif
    EXPECT_FALSE(structuralMacros({"#endif\n"}).has_value());
    EXPECT_FALSE(structuralMacros({"#else\n"}).has_value());
    // Each file balances on its own, as glslang requires.
    EXPECT_FALSE(structuralMacros({"#if A\n", "#endif\n"}).has_value());
}

// Hostile shapes: nothing, 60 nested groups with 2,000 names in every condition around
// 5,000 #defines, and an include at the bottom. Every directive refers to its groups
// instead of copying their names (a copy per line would be 600 million strings here).
TEST(StructuralMacros, HostileInputs) {
    const auto empty = structuralMacros({""});
    ASSERT_TRUE(empty.has_value());
    EXPECT_TRUE(empty->decisive.empty());
    EXPECT_TRUE(structuralMacros({}).has_value());

    std::string deep;
    for (int g = 0; g < 60; ++g) {
        deep += "#if G" + std::to_string(g);
        for (int n = 0; n < 2000; ++n) deep += " + N" + std::to_string(n);
        deep += "\n";
    }
    for (int d = 0; d < 5000; ++d) deep += "#define D" + std::to_string(d) + " 1\n";
    deep += "#include \"x.glsl\"\n";
    for (int g = 0; g < 60; ++g) deep += "#endif\n";
    const auto found = structuralMacros({deep});
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->decisive.size(), 60u + 2000u);  // G0..G59 and N0..N1999
    EXPECT_EQ(found->defined.size(), 5000u);
}

}  // namespace
}  // namespace prism::shaderc
