// Golden images of the water scene (tests/golden/water/<case>.png, 160x160, llvmpipe):
// puddles after 120 steps of cloudburst rain seen from two views, a close view with
// capillary ripples on (rain) and off (the rain stopped), and a scene without water in
// fog. Mutation tests show the comparison catches the ripples and a changed Fresnel F0.
//
// The check, its update mode and where actual and diff images go (default
// <build>/tests/water/golden-failures/water): prism/test/golden.hpp.
// image::Thresholds as there: a pixel is "over" above 3/255 in a channel; at most 0.1 % of
// pixels over and a mean absolute error of at most 0.5/255.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>

#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_scene.hpp"
#include "prism/test/golden.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::water {
namespace {

namespace fs = std::filesystem;
using WaterGlTest = ::prism::test::GlTest;

constexpr int kSize = 160;
constexpr image::Thresholds kGoldenThresholds{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};

fs::path goldenPath(const std::string& name) {
    return fs::path(PRISM_GOLDEN_DIR) / "water" / (name + ".png");
}

// The puddle scene: 64x64 cells of 0.25 m, 120 steps of 2 s of cloudburst rain on the
// CPU reference (deterministic; the GPU step gives the same bits).
WaterSceneDescription puddleDescription() {
    WaterSceneDescription d;
    d.terrain =
        proceduralTerrain({.width = 64, .height = 64, .cellSize = 0.25f, .relief = 1.0f, .pits = 5, .seed = 21});
    d.rainMmPerHour = rainRateMmPerHour(RainClass::Cloudburst);
    d.sky.faceSize = 64;
    return d;
}

void simulatePuddles(WaterScene& scene) {
    for (int i = 0; i < 120; ++i) scene.advance(2.0);
}

view::Camera closeCamera(const HeightField& t) {
    view::Camera c = groundCamera(t);
    c.eye = {-1.5f, 1.1f, 1.8f};  // above the shore of a puddle, looking across it
    c.target = {0.2f, 0.1f, -0.6f};
    return c;
}

void expectMatchesGolden(const std::string& name, const image::Image8& actual) {
    ASSERT_EQ(actual.width, kSize);
    ::prism::test::expectMatchesGolden(actual, {.golden = goldenPath(name),
                                                .outName = "water/" + name,
                                                .thresholds = kGoldenThresholds,
                                                .outDir = PRISM_GOLDEN_FAILURE_DIR});
}

// Pixels that the water changed: where the image differs from the same view without water.
std::size_t differingPixels(const image::Image8& a, const image::Image8& b) {
    return image::compareImages(a, b, 3).pixelsOver;
}

TEST_F(WaterGlTest, GoldenPuddlesFromTwoViews) {
    WaterScene scene(puddleDescription());
    simulatePuddles(scene);
    WaterSceneRenderer renderer(scene);
    const image::Image8 overview = renderer.renderImage(overviewCamera(scene.terrain()), kSize, kSize);
    const image::Image8 ground = renderer.renderImage(groundCamera(scene.terrain()), kSize, kSize);
    // Puddles must be visible: compare with the same terrain without water.
    WaterSceneDescription dry = puddleDescription();
    dry.water = false;
    WaterScene dryScene(std::move(dry));
    WaterSceneRenderer dryRenderer(dryScene);
    EXPECT_GT(differingPixels(overview, dryRenderer.renderImage(overviewCamera(scene.terrain()), kSize, kSize)),
              static_cast<std::size_t>(kSize * kSize / 50))
        << "puddles cover a visible part of the overview";
    expectMatchesGolden("puddles-overview-cloudburst-120x2s", overview);
    expectMatchesGolden("puddles-ground-cloudburst-120x2s", ground);
}

TEST_F(WaterGlTest, GoldenRipplesOnAndOff) {
    WaterScene scene(puddleDescription());
    simulatePuddles(scene);
    scene.advance(0.1);  // a ripple frame between two of the 16
    WaterSceneRenderer renderer(scene);
    const view::Camera cam = closeCamera(scene.terrain());
    const image::Image8 on = renderer.renderImage(cam, kSize, kSize);
    scene.water()->setRain(0.0);  // the same water, no rain: RIPPLES=0
    const image::Image8 off = renderer.renderImage(cam, kSize, kSize);
    const image::ImageComparison onVsOff = image::compareImages(on, off, kGoldenThresholds.maxChannelDiff);
    std::cout << "[mutation] ripples on vs off: " << image::describe(onVsOff, kGoldenThresholds) << "\n";
    EXPECT_FALSE(image::passes(onVsOff, kGoldenThresholds)) << "the ripples must be visible";
    expectMatchesGolden("ripples-on-cloudburst-close", on);
    expectMatchesGolden("ripples-off-close", off);
}

TEST_F(WaterGlTest, GoldenDryTerrainInFog) {
    WaterSceneDescription d = puddleDescription();
    d.water = false;
    d.fog = view::Fog{.color = {0.66f, 0.68f, 0.70f}, .density = 0.05f};
    WaterScene scene(std::move(d));
    WaterSceneRenderer renderer(scene);
    expectMatchesGolden("dry-terrain-fog", renderer.renderImage(groundCamera(scene.terrain()), kSize, kSize));
}

TEST_F(WaterGlTest, GoldenCatchesAChangedFresnelF0) {
    if (::prism::test::updatingGoldens()) GTEST_SKIP() << "goldens are being rewritten";
    WaterSceneDescription d = puddleDescription();
    d.look.fresnelF0 = 0.2f;  // glass-like instead of water's 0.02
    WaterScene scene(std::move(d));
    simulatePuddles(scene);
    WaterSceneRenderer renderer(scene);
    const image::Image8 mutant = renderer.renderImage(groundCamera(scene.terrain()), kSize, kSize);
    const image::ImageComparison cmp = image::compareImages(
        mutant, image::readPng(goldenPath("puddles-ground-cloudburst-120x2s")), kGoldenThresholds.maxChannelDiff);
    std::cout << "[mutation] F0 0.02 -> 0.2: " << image::describe(cmp, kGoldenThresholds) << "\n";
    EXPECT_FALSE(image::passes(cmp, kGoldenThresholds));
}

}  // namespace
}  // namespace prism::water
