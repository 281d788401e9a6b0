// "Model only what the scene requires": a scene without water has no water map, no
// simulation and no water program; a scene without rain has no ripple textures and no
// ripple animation. Shown with the GL objects and programs the renderer created.
#include <gtest/gtest.h>

#include "prism/render/feature_variants.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/procedural_textures.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_scene.hpp"
#include "prism/water_shaders.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::water {
namespace {

using WaterGlTest = ::prism::test::GlTest;

WaterSceneDescription smallScene(bool water, double rainMmPerHour) {
    WaterSceneDescription d;
    d.terrain = proceduralTerrain({.width = 32, .height = 32, .cellSize = 0.25f, .relief = 1.5f, .seed = 4});
    d.water = water;
    d.rainMmPerHour = rainMmPerHour;
    d.sky.faceSize = 16;
    return d;
}

// Whether the renderer's cache already holds `shader` with these extra axis values.
bool hasProgram(WaterSceneRenderer& r, const WaterScene& scene, const char* shader,
                const render::VariantValues& values) {
    render::ProgramCache& cache = r.programCache();
    const std::size_t before = cache.size();
    const auto& d = scene.description();
    cache.get(shader, render::variantFor(*catalog::findShader(water_shaders::kCatalog, shader),
                                         render::featuresOf(d.lights, d.fog.has_value()), values));
    return cache.size() == before;
}

TEST_F(WaterGlTest, SceneWithoutWaterHasNoWaterMapSimulationOrWaterProgram) {
    WaterScene scene(smallScene(false, rainRateMmPerHour(RainClass::Heavy)));
    EXPECT_FALSE(scene.hasWater());
    EXPECT_EQ(scene.water(), nullptr) << "no water map, no simulation";
    scene.advance(10.0);  // nothing to do
    WaterSceneRenderer renderer(scene);
    const image::Image8 img = renderer.renderImage(groundCamera(scene.terrain()), 48, 48);
    const SceneRenderStats s = renderer.stats();
    EXPECT_EQ(s.programs, 2u) << "skybox and terrain only";
    EXPECT_FALSE(s.waterSurface);
    EXPECT_FALSE(s.rippleTextures);
    EXPECT_EQ(s.textures, 1u) << "the sky cube map only";
    EXPECT_TRUE(hasProgram(renderer, scene, "terrain", {{"WET", "0"}})) << "dry terrain variant";
    EXPECT_FALSE(hasProgram(renderer, scene, "water_surface", {})) << "the water program was never built";
}

TEST_F(WaterGlTest, WaterWithoutRainHasNoRipples) {
    WaterScene scene(smallScene(true, 0.0));
    ASSERT_TRUE(scene.hasWater());
    std::vector<float> puddle(scene.terrain().cellCount(), 0.02f);
    scene.water()->simulation().setDepth(puddle);
    scene.advance(5.0);
    EXPECT_EQ(scene.water()->rippleFrame(), 0.0) << "no rain: the ripple animation stands still";
    WaterSceneRenderer renderer(scene);
    renderer.renderImage(groundCamera(scene.terrain()), 48, 48);
    const SceneRenderStats s = renderer.stats();
    EXPECT_EQ(s.programs, 3u) << "skybox, terrain, water surface";
    EXPECT_TRUE(s.waterSurface);
    EXPECT_FALSE(s.rippleTextures) << "no ripple frames without rain";
    EXPECT_EQ(s.textures, 4u) << "sky, terrain heights, water depths, terrain albedo (the ground seen through water)";
    EXPECT_TRUE(hasProgram(renderer, scene, "water_surface", {{"RIPPLES", "0"}}));
    EXPECT_TRUE(hasProgram(renderer, scene, "terrain", {{"WET", "1"}}));
}

TEST_F(WaterGlTest, RainAddsRippleFramesAnimatedByItsIntensity) {
    WaterScene scene(smallScene(true, rainRateMmPerHour(RainClass::Light)));
    WaterSceneRenderer renderer(scene);
    scene.advance(0.25);
    const double lightFrame = scene.water()->rippleFrame();
    EXPECT_NEAR(lightFrame, 0.25 * rippleFramesPerSecond(rainRateMmPerHour(RainClass::Light)), 1e-9);
    renderer.renderImage(groundCamera(scene.terrain()), 48, 48);
    EXPECT_TRUE(renderer.stats().rippleTextures);
    EXPECT_EQ(renderer.stats().textures, 5u);
    EXPECT_TRUE(hasProgram(renderer, scene, "water_surface", {{"RIPPLES", "1"}}));
    EXPECT_GT(rippleFramesPerSecond(rainRateMmPerHour(RainClass::Cloudburst)),
              rippleFramesPerSecond(rainRateMmPerHour(RainClass::Drizzle)))
        << "heavier rain animates faster";
    EXPECT_EQ(rippleFramesPerSecond(0.0), 0.0);
}

TEST_F(WaterGlTest, GpuBackendBuildsComputeProgramsOnlyForWater) {
    WaterSceneDescription d = smallScene(true, rainRateMmPerHour(RainClass::Heavy));
    d.backend = SimulationBackend::Gpu;
    WaterScene scene(std::move(d));
    auto* gpu = dynamic_cast<GpuWaterSimulation*>(&scene.water()->simulation());
    ASSERT_NE(gpu, nullptr);
    EXPECT_EQ(gpu->programCount(), 8u) << "six step passes and two ledger reductions";
    scene.advance(2.0);
    WaterSceneRenderer renderer(scene);
    const image::Image8 img = renderer.renderImage(overviewCamera(scene.terrain()), 48, 48);
    EXPECT_EQ(img.width, 48);
    // The same scene without water builds no compute programs at all.
    WaterSceneDescription dry = smallScene(false, 0.0);
    dry.backend = SimulationBackend::Gpu;
    WaterScene dryScene(std::move(dry));
    EXPECT_EQ(dryScene.water(), nullptr);
}

}  // namespace
}  // namespace prism::water
