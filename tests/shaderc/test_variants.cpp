// Variant axes from pragmas, --variant filters and the enumeration of combinations.
#include <gtest/gtest.h>

#include "variants.hpp"

using namespace prism::shaderc;

TEST(Variants, BooleanAndValuedAxes) {
    auto r = axesFromPragmas({{"FOG", {}, "a.frag", 1}, {"LIGHTS", {"1", "2", "4"}, "l.glsl", 3}});
    ASSERT_TRUE(r.diagnostics.empty());
    ASSERT_EQ(r.axes.size(), 2u);
    EXPECT_EQ(r.axes[0].values, (std::vector<std::string>{"0", "1"}));
    auto c = variantChoices("s", r.axes, {});
    ASSERT_EQ(c.choices.size(), 6u);
    EXPECT_EQ(c.choices.front().name, "FOG=0,LIGHTS=1");
    EXPECT_EQ(c.choices.back().name, "FOG=1,LIGHTS=4");
}

TEST(Variants, SameDeclarationTwiceMergesConflictingIsAnError) {
    auto same = axesFromPragmas({{"FOG", {}, "a.frag", 1}, {"FOG", {"0", "1"}, "b.glsl", 2}});
    EXPECT_TRUE(same.diagnostics.empty());
    EXPECT_EQ(same.axes.size(), 1u);
    auto clash = axesFromPragmas({{"N", {"1", "2"}, "a.frag", 1}, {"N", {"1", "4"}, "b.glsl", 7}});
    ASSERT_EQ(clash.diagnostics.size(), 1u);
    EXPECT_EQ(clash.diagnostics[0].file, "b.glsl");
    EXPECT_EQ(clash.diagnostics[0].line, 7);
    ASSERT_EQ(clash.diagnostics[0].notes.size(), 1u);
    EXPECT_EQ(clash.diagnostics[0].notes[0].file, "a.frag");
}

TEST(Variants, NoAxesGivesTheDefaultVariant) {
    auto c = variantChoices("s", {}, {});
    ASSERT_EQ(c.choices.size(), 1u);
    EXPECT_EQ(c.choices[0].name, "default");
    EXPECT_TRUE(c.choices[0].defines.empty());
}

TEST(Variants, FiltersSelectOnlyTheAskedCombinations) {
    std::vector<Axis> axes{{"FOG", {"0", "1"}}, {"LIGHTS", {"1", "2", "4"}}};
    auto f = parseVariantFilters({"s:FOG=0,LIGHTS=2", "s:FOG=1", "other:X=1"});
    ASSERT_TRUE(f.diagnostics.empty());
    auto c = variantChoices("s", axes, f.filters);
    ASSERT_TRUE(c.diagnostics.empty());
    std::vector<std::string> names;
    for (const auto& ch : c.choices) names.push_back(ch.name);
    EXPECT_EQ(names,
              (std::vector<std::string>{"FOG=0,LIGHTS=2", "FOG=1,LIGHTS=1", "FOG=1,LIGHTS=2", "FOG=1,LIGHTS=4"}));
}

TEST(Variants, FilterNamingUnknownAxisOrValueIsAnError) {
    std::vector<Axis> axes{{"FOG", {"0", "1"}}};
    auto f = parseVariantFilters({"s:FOGG=1", "s:FOG=2"});
    auto c = variantChoices("s", axes, f.filters);
    ASSERT_EQ(c.diagnostics.size(), 2u);
    EXPECT_NE(c.diagnostics[0].message.find("declares no variant 'FOGG'"), std::string::npos);
    EXPECT_NE(c.diagnostics[1].message.find("has no value '2'"), std::string::npos);
}

TEST(Variants, MalformedFilterSpec) {
    auto f = parseVariantFilters({"noColon", "s:FOG", "s:=1"});
    EXPECT_EQ(f.diagnostics.size(), 3u);
    EXPECT_TRUE(f.filters.empty());
}

TEST(Variants, WildcardFilterAppliesToEveryShaderWithThatAxis) {
    auto f = parseVariantFilters({"*:LIGHTS=2"});
    ASSERT_TRUE(f.diagnostics.empty());
    std::vector<Axis> withLights{{"FOG", {"0", "1"}}, {"LIGHTS", {"1", "2", "4"}}};
    auto c = variantChoices("lit", withLights, f.filters);
    ASSERT_TRUE(c.diagnostics.empty());
    ASSERT_EQ(c.choices.size(), 2u);
    EXPECT_EQ(c.choices[0].name, "FOG=0,LIGHTS=2");
    std::vector<Axis> unlit{{"FOG", {"0", "1"}}};
    auto u = variantChoices("unlit", unlit, f.filters);
    EXPECT_TRUE(u.diagnostics.empty());
    EXPECT_EQ(u.choices.size(), 2u);  // the axis it lacks is ignored
}
