// Golden images of the rain scene (tests/golden/rain/<case>.png, 160x160, llvmpipe):
// two views, with and without wind, and with fog; plus the three streak techniques
// against each other, light dependence of the streaks, and byte-identical repeats.
//
// image::Thresholds as in tests/rendering (tests/golden/README.md): a pixel is "over" when a
// channel differs by more than 3/255; a case passes with at most 0.1 % of pixels over
// and a mean absolute error of at most 0.5/255.
// The check, its update mode and where actual and diff images go (default
// <build>/tests/rain/golden-failures): prism/test/golden.hpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/test/golden.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rain::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 160;
constexpr int kWarmupSteps = 20;  // of 1/30 s
constexpr image::Thresholds kThresholds{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};

struct RainCase {
    std::string name;  // the golden's file name, self-describing
    int view = 0;
    RainClass rain = RainClass::Moderate;
    float wind = 0.0f;
    bool fog = false;
    StreakTechnique technique = StreakTechnique::GeometryShader;
};

void PrintTo(const RainCase& c, std::ostream* os) {
    *os << c.name;
}

const std::vector<RainCase>& goldenCases() {
    static const std::vector<RainCase> cases = {
        {"view0-moderate-calm", 0, RainClass::Moderate, 0.0f, false},
        {"view0-moderate-wind7", 0, RainClass::Moderate, 7.0f, false},
        {"view1-heavy-calm", 1, RainClass::Heavy, 0.0f, false},
        {"view1-heavy-wind7", 1, RainClass::Heavy, 7.0f, false},
        {"view0-moderate-calm-fog", 0, RainClass::Moderate, 0.0f, true},
    };
    return cases;
}

RainSceneDesc describe(const RainCase& c, std::uint32_t seed = 2013) {
    RainSceneDesc d = defaultRainScene();
    d.camera = rainSceneView(c.view);
    d.rain->seed = seed;
    d.rain->intensity = rainClassInfo(c.rain).intensity;
    d.rain->wind.strength = c.wind;
    d.rain->wind.directionDegrees = 200.0f;
    if (c.fog) d.fog = SceneFog{};
    d.technique = c.technique;
    return d;
}

image::Image8 renderScene(const RainSceneDesc& d) {
    RainScene scene(d);
    for (int i = 0; i < kWarmupSteps; ++i) scene.update(1.0f / 30.0f);
    return scene.render(kSize, kSize);
}

fs::path goldenPath(const std::string& name) {
    return fs::path(PRISM_RAIN_GOLDEN_DIR) / (name + ".png");
}

// Pixels that differ from `reference` by more than `tolerance` in any channel.
std::size_t changedPixels(const image::Image8& a, const image::Image8& reference, int tolerance = 2) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.data.size(); i += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.data[i + c]) - int(reference.data[i + c])));
        n += d > tolerance ? 1 : 0;
    }
    return n;
}

// Sum over pixels of how much brighter `a` is than `reference` (RGB, 8-bit units).
double addedLight(const image::Image8& a, const image::Image8& reference) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.data.size(); i += 4)
        for (int c = 0; c < 3; ++c) sum += std::max(0, int(a.data[i + c]) - int(reference.data[i + c]));
    return sum;
}

class RainGolden : public ::prism::test::GlTest, public ::testing::WithParamInterface<RainCase> {};

TEST_P(RainGolden, MatchesStoredGoldenWithinThresholds) {
    const RainCase& c = GetParam();
    const image::Image8 actual = renderScene(describe(c));
    RainSceneDesc dry = describe(c);
    dry.rain.reset();
    // A golden without visible rain would test nothing.
    ASSERT_GT(changedPixels(actual, renderScene(dry)), actual.pixelCount() / 50)
        << c.name << ": (almost) no rain drawn";

    ::prism::test::expectMatchesGolden(actual, {.golden = goldenPath(c.name),
                                                .outName = c.name,
                                                .thresholds = kThresholds,
                                                .outDir = PRISM_RAIN_GOLDEN_FAILURE_DIR});
}

INSTANTIATE_TEST_SUITE_P(Scenes, RainGolden, ::testing::ValuesIn(goldenCases()),
                         [](const ::testing::TestParamInfo<RainCase>& info) {
                             std::string n = info.param.name;
                             for (char& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

class RainImages : public ::prism::test::GlTest {};

TEST_F(RainImages, RepeatedRenderIsByteIdentical) {
    const RainSceneDesc d = describe(goldenCases()[1]);
    EXPECT_EQ(renderScene(d), renderScene(d));
}

// The thresholds catch a real change: another random seed, or the wind turned by 20 deg.
TEST_F(RainImages, GoldenComparisonCatchesChanges) {
    const RainCase& c = goldenCases()[1];
    const image::Image8 base = renderScene(describe(c));
    const image::Image8 otherSeed = renderScene(describe(c, 2014));
    EXPECT_FALSE(image::passes(image::compareImages(otherSeed, base, 3), kThresholds));
    RainSceneDesc turned = describe(c);
    turned.rain->wind.directionDegrees = 220.0f;
    EXPECT_FALSE(image::passes(image::compareImages(renderScene(turned), base, 3), kThresholds));
}

// Instanced quads are the geometry-shader quads drawn another way: same image within
// the golden thresholds. Point sprites cut the same streaks out of squares: about the
// same amount of light.
TEST_F(RainImages, TechniquesDrawTheSameStreaks) {
    RainCase c = goldenCases()[1];
    RainSceneDesc dryDesc = describe(c);
    dryDesc.rain.reset();
    const image::Image8 dry = renderScene(dryDesc);
    const image::Image8 gs = renderScene(describe(c));
    c.technique = StreakTechnique::Instanced;
    const image::Image8 instanced = renderScene(describe(c));
    const image::ImageComparison cmp = image::compareImages(instanced, gs, 3);
    EXPECT_TRUE(image::passes(cmp, kThresholds)) << prism::image::describe(cmp, kThresholds);
    c.technique = StreakTechnique::PointSprites;
    const image::Image8 points = renderScene(describe(c));
    const double gsLight = addedLight(gs, dry), pointLight = addedLight(points, dry);
    std::cout << "[ info ] light added by the rain: gs " << gsLight << ", instanced " << addedLight(instanced, dry)
              << ", points " << pointLight << "\n";
    EXPECT_GT(pointLight, 0.6 * gsLight);
    EXPECT_LT(pointLight, 1.5 * gsLight);
}

// The streak texture makes drops back-lit by the sun brighter than drops lit from
// behind the camera (the light-dependence of Garg & Nayar / Tariq).
TEST_F(RainImages, BackLitRainIsBrighterThanFrontLitRain) {
    auto rainLight = [](glm::vec3 sunDirection) {
        RainSceneDesc d = describe(goldenCases()[0]);
        d.camera.eye = {0.0f, 1.7f, 0.0f};
        d.camera.target = {0.0f, 4.0f, -10.0f};  // looking along -z, a little up, at the sky
        d.lights.ambient = glm::vec3(0.0f);
        d.lights.lamp.color = glm::vec3(0.0f);
        d.lights.sun.direction = sunDirection;
        d.lights.sun.color = glm::vec3(1.0f);
        d.showLampBulb = false;
        RainSceneDesc dry = d;
        dry.rain.reset();
        return addedLight(renderScene(d), renderScene(dry));
    };
    const double backLit = rainLight({0.0f, -0.3f, 1.0f});    // sun ahead, shining towards the camera
    const double frontLit = rainLight({0.0f, -0.3f, -1.0f});  // sun behind the camera
    std::cout << "[ info ] rain light, back-lit " << backLit << ", front-lit " << frontLit << "\n";
    EXPECT_GT(backLit, 2.0 * frontLit);
}

}  // namespace
}  // namespace prism::rain::test
