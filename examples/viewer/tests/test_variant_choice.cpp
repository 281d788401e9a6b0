// Unit tests of the catalogue panel's variant logic (variant_choice.hpp) on a hand-made
// shader whose catalogue lacks one combination, as when a variant fails validation.
#include <gtest/gtest.h>

#include <string_view>

#include "variant_choice.hpp"

namespace {

using prism::catalog::Define;
using prism::catalog::Shader;
using prism::catalog::Variant;
using prism::catalog::VariantAxis;

constexpr std::string_view kBool[] = {"0", "1"};
constexpr std::string_view kLights[] = {"0", "1", "2"};
constexpr VariantAxis kAxes[] = {{"BLINN", kBool}, {"DIRECTIONAL_LIGHTS", kLights}};
// Every combination except BLINN=1 with DIRECTIONAL_LIGHTS=2.
constexpr Define kV0[] = {{"BLINN", "0"}, {"DIRECTIONAL_LIGHTS", "0"}};
constexpr Define kV1[] = {{"BLINN", "0"}, {"DIRECTIONAL_LIGHTS", "1"}};
constexpr Define kV2[] = {{"BLINN", "0"}, {"DIRECTIONAL_LIGHTS", "2"}};
constexpr Define kV3[] = {{"BLINN", "1"}, {"DIRECTIONAL_LIGHTS", "0"}};
constexpr Define kV4[] = {{"BLINN", "1"}, {"DIRECTIONAL_LIGHTS", "1"}};
constexpr Variant kVariants[] = {{"a", kV0, {}, {}, {}},
                                 {"b", kV1, {}, {}, {}},
                                 {"c", kV2, {}, {}, {}},
                                 {"d", kV3, {}, {}, {}},
                                 {"e", kV4, {}, {}, {}}};
constexpr Shader kShader{"test", kAxes, kVariants, {}};

using prism::render::FeatureSet;
using prism::render::VariantValues;
using prism::viewer::effectiveVariant;
using prism::viewer::isValidChoice;
using prism::viewer::variantLabel;

TEST(VariantChoice, LightAxesFollowTheLightsAndPicksTheRest) {
    EXPECT_EQ(variantLabel(effectiveVariant(kShader, FeatureSet{.directionalLights = 2}, {})),
              "BLINN=0,DIRECTIONAL_LIGHTS=2");
    EXPECT_EQ(variantLabel(effectiveVariant(kShader, FeatureSet{.directionalLights = 1}, {{"BLINN", "1"}})),
              "BLINN=1,DIRECTIONAL_LIGHTS=1");
}

TEST(VariantChoice, MissingCombinationsAreGreyedOut) {
    const VariantValues twoLights{{"BLINN", "0"}, {"DIRECTIONAL_LIGHTS", "2"}};
    EXPECT_FALSE(isValidChoice(kShader, twoLights, "BLINN", "1"));
    EXPECT_TRUE(isValidChoice(kShader, twoLights, "BLINN", "0"));
    const VariantValues blinn{{"BLINN", "1"}, {"DIRECTIONAL_LIGHTS", "1"}};
    EXPECT_TRUE(isValidChoice(kShader, blinn, "DIRECTIONAL_LIGHTS", "0"));
    EXPECT_FALSE(isValidChoice(kShader, blinn, "DIRECTIONAL_LIGHTS", "2"));
    EXPECT_FALSE(isValidChoice(kShader, blinn, "DIRECTIONAL_LIGHTS", "3"));  // not a value of the axis
}

TEST(VariantChoice, AMissingCombinationFallsBackToTheDerivedVariant) {
    // BLINN=1 was picked, then the lights grew to two: that combination does not exist,
    // so the view runs the derived variant instead of failing.
    EXPECT_EQ(variantLabel(effectiveVariant(kShader, FeatureSet{.directionalLights = 2}, {{"BLINN", "1"}})),
              "BLINN=0,DIRECTIONAL_LIGHTS=2");
}

TEST(VariantChoice, PicksForAxesTheShaderLacksAreIgnored) {
    // BLINN picked on phong stays picked when gouraud (no BLINN axis) is shown.
    EXPECT_EQ(variantLabel(effectiveVariant(kShader, FeatureSet{.directionalLights = 1}, {{"WET", "1"}})),
              "BLINN=0,DIRECTIONAL_LIGHTS=1");
}

TEST(VariantChoice, PicksThatNameNoVariantAreExplained) {
    using prism::viewer::whyNotAVariant;
    const FeatureSet twoLights{.directionalLights = 2};
    EXPECT_EQ(whyNotAVariant(kShader, twoLights, {{"BLINN", "0"}}), "");
    EXPECT_EQ(whyNotAVariant(kShader, twoLights, {{"WET", "1"}}),
              "test has no variant axis 'WET' (its axes: BLINN, DIRECTIONAL_LIGHTS)");
    EXPECT_EQ(whyNotAVariant(kShader, twoLights, {{"BLINN", "7"}}),
              "BLINN=7 is not a value of test's axis BLINN (values: 0, 1)");
    EXPECT_EQ(whyNotAVariant(kShader, twoLights, {{"BLINN", "1"}}),
              "test has no generated variant BLINN=1,DIRECTIONAL_LIGHTS=2");
}

}  // namespace
