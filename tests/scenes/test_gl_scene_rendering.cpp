// Scenes rendered with minimal variants: a one-light, no-fog scene's programs have no
// fog uniforms and a light loop bound of 1; draws with the same feature set share a
// program; the example scenes match their golden images (tests/golden/scenes/; the check,
// its update mode and the failure images: prism/test/golden.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <memory>
#include <variant>
#include <utility>
#include <vector>

#include "prism/render/feature_variants.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_simulation.hpp"
#include "prism/water/height_field.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/scene/stochastic.hpp"
#include "prism/shaders.hpp"
#include "prism/test/golden.hpp"
#include "prism/test/gl_test.hpp"

namespace fs = std::filesystem;

namespace {

prism::scene::Scene exampleScene(const std::string& name) {
    return prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/" + name + ".json");
}

// The example grating, small and cheap: `size`² pixels, `tableSize`² tables, `terms` terms.
prism::scene::Scene smallGrating(int size, int tableSize, int terms) {
    auto scene = exampleScene("diffraction_grating");
    scene.width = scene.height = size;
    auto& m = *scene.objects[0].diffraction;
    m.tableSize = tableSize;
    m.terms = terms;
    return scene;
}

// Golden thresholds: llvmpipe renders byte-identically run to run, so these only absorb
// driver or technique changes (docs/references.md, "Golden-image testing"): a pixel counts as different above 3/255 in
// a channel; at most 0.1 % of pixels may, and the mean error must stay <= 0.5/255.
const prism::image::Thresholds kThresholds{3, 0.001, 0.5};

// The golden of an example scene (tests/golden/scenes/<name>.png) with the thresholds above.
prism::test::GoldenCheck sceneGolden(const std::string& name) {
    return {.golden = fs::path(PRISM_GOLDEN_DIR) / "scenes" / (name + ".png"),
            .outName = "scenes/" + name,
            .thresholds = kThresholds,
            .outDir = PRISM_GOLDEN_FAILURE_DIR};
}

class SceneGoldenMutation : public prism::test::GlTest {};
class SceneRendering : public prism::test::GlTest {};
class StochasticScene : public prism::test::GlTest {};

}  // namespace

TEST_F(SceneRendering, OneLightNoFogProgramHasNoFogUniformsAndLoopBoundOne) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("one_light");
    scene.width = scene.height = 64;
    renderer.render(scene);
    ASSERT_EQ(renderer.lastFrame().draws, scene.objects.size());
    for (const auto& object : scene.objects) {
        const auto* shader = prism::catalog::findShader(prism::shaders::kCatalog, object.shader);
        ASSERT_NE(shader, nullptr);
        const auto& variant = renderer.programs().variantOf(
            object.shader, prism::render::variantFor(*shader, prism::render::featuresOf(scene.lights, false)));
        for (const auto& d : variant.defines) {
            if (d.name == "DIRECTIONAL_LIGHTS") {
                EXPECT_EQ(d.value, "1");
            }
            if (d.name == "FOG") {
                EXPECT_EQ(d.value, "0");
            }
        }
        const auto text = prism::catalog::joinChunks(variant.stages.back().chunks);
        EXPECT_NE(text.find("#define DIRECTIONAL_LIGHTS 1\n"), std::string::npos);
        // The fog module is not even included (its call sites sit under #if FOG).
        EXPECT_EQ(text.find("vec3 applyFog("), std::string::npos) << "no fog code without fog";
        EXPECT_EQ(text.find("uniform float u_fogDensity"), std::string::npos);
        for (const auto& u : variant.uniforms) {
            EXPECT_EQ(std::string(u.name).find("u_fog"), std::string::npos) << object.shader;
            EXPECT_EQ(std::string(u.name).find("u_pointLight"), std::string::npos) << object.shader;
            if (u.name == "u_lightDirection") {
                EXPECT_EQ(u.arraySize, 1) << object.shader;
            }
        }
    }
}

TEST_F(SceneRendering, DrawsWithTheSameFeatureSetShareOneProgram) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("four_lights");  // two phong spheres and a flat floor
    scene.width = scene.height = 64;
    renderer.render(scene);
    EXPECT_EQ(renderer.lastFrame().draws, 3u);
    EXPECT_EQ(renderer.programs().size(), 2u);
    EXPECT_EQ(renderer.lastFrame().variants[0], renderer.lastFrame().variants[1]);
    renderer.render(scene);  // a second frame builds nothing new
    EXPECT_EQ(renderer.programs().size(), 2u);
}

TEST_F(SceneRendering, FogSceneUsesFogVariantsOnly) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("fog");
    scene.width = scene.height = 64;
    renderer.render(scene);
    for (const auto& v : renderer.lastFrame().variants) EXPECT_NE(v.find("FOG=1"), std::string::npos) << v;
}

TEST_F(SceneRendering, UnknownShaderListsTheKnownOnes) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = prism::scene::parseScene(R"({"objects": [{"material": {"shader": "toon"}}]})", "toon.json");
    try {
        renderer.render(scene);
        FAIL() << "no error";
    } catch (const prism::render::UnknownShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown shader 'toon'; known shaders: flat, gouraud, phong"),
                  std::string::npos)
            << e.what();
    }
}

TEST_F(SceneRendering, NoRainNoRainSystemAndNoRainProgram) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("one_light");
    scene.width = scene.height = 64;
    renderer.render(scene);
    EXPECT_EQ(renderer.rainSystemsCreated(), 0u);
    EXPECT_EQ(renderer.rainProgramsBuilt(), 0u);
    EXPECT_EQ(renderer.waterSystemsCreated(), 0u);
}

TEST_F(SceneRendering, WaterSceneSimulatesAndDrawsTheWaterMap) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("water");
    scene.width = 128;
    scene.height = 96;
    scene.rain.reset();  // water fed by its own rain rate, no particles drawn
    scene.water->seconds = 10.0;
    renderer.render(scene);
    EXPECT_EQ(renderer.waterSystemsCreated(), 1u);
    EXPECT_EQ(renderer.rainSystemsCreated(), 0u);
    ASSERT_FALSE(renderer.lastFrame().variants.empty());
    EXPECT_EQ(renderer.lastFrame().variants.front().rfind("water 128x128", 0), 0u);
}

// Water, rain and fog billboards all stand on the scene's terrain: it is built once a frame.
TEST_F(SceneRendering, WaterRainAndFogShareOneTerrainPerFrame) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("water");
    scene.width = 96;
    scene.height = 64;
    scene.water->gridSize = 32;
    scene.water->seconds = 1.0;
    ASSERT_TRUE(scene.rain && scene.fogBillboards);
    renderer.render(scene);
    EXPECT_EQ(renderer.terrainsBuilt(), 1u);
    renderer.render(scene);
    EXPECT_EQ(renderer.terrainsBuilt(), 2u);
    scene.water.reset();
    renderer.render(scene);
    EXPECT_EQ(renderer.terrainsBuilt(), 2u) << "no terrain without water";
}

TEST_F(SceneRendering, RainSceneRunsTheRainSystemOverTheObjects) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("rain");
    scene.width = 128;
    scene.height = 96;
    auto withRain = renderer.render(scene);
    EXPECT_EQ(renderer.rainSystemsCreated(), 1u);
    EXPECT_GT(renderer.rainProgramsBuilt(), 0u);
    ASSERT_FALSE(renderer.lastFrame().variants.empty());
    EXPECT_EQ(renderer.lastFrame().variants.back().rfind("rain gs-quads", 0), 0u);
    auto dry = scene;
    dry.rain.reset();
    auto withoutRain = renderer.render(dry);
    EXPECT_EQ(renderer.rainSystemsCreated(), 1u);  // the dry frame made none
    auto cmp = prism::image::compareImages(withRain, withoutRain);
    EXPECT_GT(cmp.pixelsOver, 100u) << "the streaks must show";
}

// The viewer's rain panel: technique and level-of-detail rings reach the rain system.
TEST_F(SceneRendering, RainTechniqueAndRingsApply) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("rain");
    scene.width = 96;
    scene.height = 64;
    renderer.render(scene);
    const std::string fourRings = renderer.lastFrame().variants.back();
    scene.rain->technique = prism::rain::StreakTechnique::PointSprites;
    scene.rain->lodRings = 1;
    renderer.render(scene);
    const std::string oneRing = renderer.lastFrame().variants.back();
    EXPECT_EQ(oneRing.rfind("rain point-sprites (", 0), 0u) << oneRing;
    auto particles = [](const std::string& s) { return std::stoul(s.substr(s.find('(') + 1)); };
    // One ring is full density out to the cylinder's edge; four fall off by 0.5 per ring
    // (rain_params.hpp's V_LOD), so one ring holds more drops.
    EXPECT_GT(particles(oneRing), particles(fourRings));
}

TEST_F(SceneRendering, RainSettingsMapToRainParameters) {
    prism::scene::RainSettings s;
    s.intensityClass = prism::rain::RainClass::Cloudburst;
    s.wind = {0.0f, 0.0f, 3.0f};
    auto p = prism::scene::rainParamsFor(s);
    EXPECT_NEAR(p.wind.strength, 3.0f, 1e-6f);
    ASSERT_TRUE(p.wind.directionDegrees.has_value());
    EXPECT_NEAR(*p.wind.directionDegrees, 90.0f, 1e-4f);
    s.rateMillimetresPerHour = 13.81;
    EXPECT_NEAR(prism::scene::rainParamsFor(s).intensity, 1.381f, 1e-5f);  // mm/h -> cm/h
    s.rateMillimetresPerHour = -1.0;
    EXPECT_THROW(prism::scene::rainParamsFor(s), std::invalid_argument);
}

// examples/scenes/water.json: eye at 9 m over terrain 0-3 m. The rain must fall onto the
// terrain it feeds (it used to stop 4 m under the eye, at 5 m).
TEST_F(SceneRendering, RainReachesTheTerrainInTheWaterScene) {
    const prism::scene::Scene scene = exampleScene("water");
    ASSERT_TRUE(scene.rain && scene.water);
    const prism::rain::RainParams p = prism::scene::rainParamsFor(scene);
    const prism::water::HeightField t = prism::scene::sceneTerrain(*scene.water);
    prism::rain::CpuRainSimulation sim(p, scene.camera.eye);
    for (int i = 0; i < 90; ++i) sim.step(1.0f / 30.0f, scene.camera.eye);
    int onTerrain = 0, belowTerrain = 0;
    for (const auto& q : sim.particles()) {
        // The terrain is centred on the origin (WaterSceneRenderer's model matrix).
        const float gx = (q.position.x + 0.5f * t.sizeX()) / t.cellSize;
        const float gz = (q.position.z + 0.5f * t.sizeZ()) / t.cellSize;
        if (gx < 0.0f || gz < 0.0f || gx > static_cast<float>(t.width - 1) || gz > static_cast<float>(t.height - 1))
            continue;
        const float ground = t.at(static_cast<int>(gx + 0.5f), static_cast<int>(gz + 0.5f));
        if (q.position.y < ground)
            ++belowTerrain;
        else if (q.position.y < ground + 0.5f)
            ++onTerrain;
    }
    EXPECT_GT(onTerrain, 100) << "drops within 0.5 m above the terrain";
    EXPECT_GT(belowTerrain, 0) << "the cylinder reaches the lowest ground, so some drops pass under higher ground";
}

TEST_F(SceneRendering, NoDiffractionMaterialNoDiffractionTablesOrProgram) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = exampleScene("four_lights");
    scene.width = scene.height = 64;
    renderer.render(scene);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 0u);
    EXPECT_EQ(renderer.diffractionProgramsBuilt(), 0u);
    EXPECT_EQ(renderer.lastFrame().diffractionTableBytes, 0u);
}

// Only the chosen path's tables are built, with N terms: path b has 2N + 1 RGB layers, path a
// N + 1 RG layers plus the wavelength row; the program is the variant of that path.
TEST_F(SceneRendering, DiffractionObjectBuildsOnlyItsPathsTables) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = smallGrating(64, 64, 4);
    auto& m = *scene.objects[0].diffraction;
    renderer.render(scene);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 1u);
    EXPECT_EQ(renderer.diffractionProgramsBuilt(), 1u);
    EXPECT_EQ(renderer.programs().size(), 0u) << "no classic program for a diffraction-only scene";
    ASSERT_EQ(renderer.lastFrame().variants.size(), 1u);
    EXPECT_EQ(renderer.lastFrame().variants[0].rfind(
                  "diffraction FOG=0,DIRECTIONAL_LIGHTS=1,POINT_LIGHTS=0,DIFFRACTION_PATH=1", 0),
              0u)
        << renderer.lastFrame().variants[0];
    EXPECT_EQ(renderer.lastFrame().diffractionTableBytes, std::size_t{9} * 64 * 64 * 3 * sizeof(float));
    m.path = 'a';
    m.wavelengthStepNm = 20;  // 21 wavelengths
    renderer.render(scene);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 2u);
    EXPECT_EQ(renderer.diffractionProgramsBuilt(), 2u);
    EXPECT_NE(renderer.lastFrame().variants[0].find("DIFFRACTION_PATH=0"), std::string::npos);
    EXPECT_EQ(renderer.lastFrame().diffractionTableBytes,
              std::size_t{5} * 64 * 64 * 2 * sizeof(float) + std::size_t{21} * 4 * sizeof(float));
}

// Tables belong to the material, not the frame: a second frame of the same material, or of
// one seen before, builds nothing and draws the same image.
TEST_F(SceneRendering, DiffractionTablesAreBuiltOncePerMaterial) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = smallGrating(48, 32, 3);
    auto& m = *scene.objects[0].diffraction;
    const auto first = renderer.render(scene);
    EXPECT_EQ(renderer.render(scene).data, first.data);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 1u);
    EXPECT_GT(renderer.lastFrame().diffractionTableBytes, 0u) << "a cached set still counts in the frame";
    m.terms = 4;
    const auto fourTerms = renderer.render(scene);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 2u);
    EXPECT_NE(fourTerms.data, first.data) << "a changed material got the old tables";
    m.terms = 3;
    renderer.render(scene);
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 2u);
}

// A scene's fog covers its diffraction objects too: the FOG variant, fogged towards the fog
// colour; without fog the FOG=0 program (no fog code).
TEST_F(SceneRendering, DiffractionObjectsAreFoggedLikeTheRest) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = smallGrating(48, 32, 3);
    const auto clear = renderer.render(scene);
    EXPECT_NE(renderer.lastFrame().variants[0].find("FOG=0"), std::string::npos) << renderer.lastFrame().variants[0];
    scene.fog = prism::view::Fog{.color = {1.0f, 0.0f, 1.0f}, .density = 5.0f};
    const auto fogged = renderer.render(scene);
    EXPECT_NE(renderer.lastFrame().variants[0].find("FOG=1"), std::string::npos) << renderer.lastFrame().variants[0];
    const auto centre = fogged.at(24, 24);
    EXPECT_GT(centre[0], 200) << "dense magenta fog over the grating";
    EXPECT_LT(centre[1], 40);
    EXPECT_GT(centre[2], 200);
    EXPECT_NE(clear.at(24, 24), centre);
}

TEST_F(SceneRendering, DiffractionTooManyTermsNamesTheMaterial) {
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto scene = prism::scene::parseScene(R"({"objects": [{"mesh": "grid", "material": {"shader": "diffraction",
        "diffraction": {"height_field": {"type": "sinusoid", "amplitude_nm": 100000}, "table_size": 16}}}]})",
                                          "deep.json");
    try {
        renderer.render(scene);
        FAIL() << "no error";
    } catch (const prism::scene::SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("deep.json: /objects/0/material/diffraction/tolerance: ", 0), 0u)
            << e.what();
    }
    EXPECT_EQ(renderer.diffractionTablesBuilt(), 0u);
}

class SceneGolden : public prism::test::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SceneGolden, MatchesTheGoldenImage) {
    auto scene = exampleScene(GetParam());
    scene.width /= 2;  // 256x192: small goldens, same framing
    scene.height /= 2;
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    const auto actual = renderer.render(scene);
    prism::test::expectMatchesGolden(actual, sceneGolden(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(ExampleScenes, SceneGolden,
                         ::testing::Values("one_light", "four_lights", "fog", "rain", "water", "puddles_closeup",
                                           "diffraction_cd", "diffraction_grating", "diffraction_snake",
                                           "soft_shadows"));

// Mutation check: the grating golden pins the period. At 2400 nm instead of 2500 nm every order
// moves (sin t = sin 75 - m lambda / d), and the image must fail the golden's thresholds.
TEST_F(SceneGoldenMutation, GratingPeriod2400FailsTheGolden) {
    auto scene = exampleScene("diffraction_grating");
    scene.width /= 2;
    scene.height /= 2;
    auto& grating = std::get<prism::diffraction::GratingParams>(scene.objects[0].diffraction->heightField);
    ASSERT_DOUBLE_EQ(grating.periodNm, 2500.0);
    grating.periodNm = 2400.0;
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    const auto mutated = renderer.render(scene);
    prism::test::expectFailsGolden(mutated, sceneGolden("diffraction_grating"), "a 2400 nm grating");
    std::printf("2400 nm vs the 2500 nm golden: %s\n",
                prism::test::compareWithGolden(mutated, sceneGolden("diffraction_grating")).message.c_str());
}

// --- The stochastic effect: goldens of the three samplers, with mutation checks --------
//
// examples/scenes/soft_shadows.json at its full 128x128, 1 spp, frame 0, once per sampler
// (tests/golden/scenes/soft_shadows_<sampler>.png). The effect runs on the CPU in double
// precision and is deterministic, so the same kThresholds apply (over 3/255 on at most
// 0.1 % of pixels = 16 pixels, mean <= 0.5/255); they absorb a compiler rounding a
// penumbra sample the other way, not a different sampler or frame: the mutation test
// checks that every other sampler and frame 1 of the same sampler fail the golden.

namespace {

const char* const kSamplers[] = {"white", "bluenoise", "sorted"};

prism::image::Image8 renderStochasticScene(const std::string& sampler, int frame) {
    auto scene = exampleScene("soft_shadows");
    scene.stochastic->sampler = *prism::scene::parseStochasticSampler(sampler);
    scene.stochastic->frame = frame;
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    auto image = renderer.render(scene);
    EXPECT_EQ(renderer.lastFrame().draws, 0u) << "the stochastic effect draws nothing with GL";
    return image;
}

prism::test::GoldenCheck stochasticGolden(const std::string& sampler) {
    return sceneGolden("soft_shadows_" + sampler);
}

}  // namespace

class StochasticGolden : public prism::test::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(StochasticGolden, MatchesTheGoldenImage) {
    const auto actual = renderStochasticScene(GetParam(), 0);
    prism::test::expectMatchesGolden(actual, stochasticGolden(GetParam()));
}

TEST_P(StochasticGolden, AnotherSamplerOrFrameFailsTheGolden) {
    std::vector<std::pair<std::string, prism::image::Image8>> mutants;
    for (const char* other : kSamplers)
        if (GetParam() != other) mutants.emplace_back(std::string("sampler ") + other, renderStochasticScene(other, 0));
    mutants.emplace_back("frame 1", renderStochasticScene(GetParam(), 1));
    for (const auto& [what, image] : mutants) prism::test::expectFailsGolden(image, stochasticGolden(GetParam()), what);
}

INSTANTIATE_TEST_SUITE_P(Samplers, StochasticGolden, ::testing::Values("white", "bluenoise", "sorted"));

TEST_F(StochasticScene, AccumulatedFramesConvergeTowardsTheReference) {
    // The mean of 16 frames is closer to a 256-spp reference than frame 0 alone, for
    // every sampler; blue noise's frame 0 has a lower blurred error than white's.
    auto scene = exampleScene("soft_shadows");
    auto& st = *scene.stochastic;
    const int w = 64, h = 64;
    const auto reference = prism::bluenoise::renderReference(st.light, w, h, 256);
    double blurred[2] = {0, 0};
    for (const char* sampler : kSamplers) {
        st.sampler = *prism::scene::parseStochasticSampler(sampler);
        st.frame = 0;
        st.frames = 1;
        const auto one =
            prism::bluenoise::compareToReference(prism::scene::renderStochasticValues(st, w, h), reference);
        st.frames = 16;
        const auto many =
            prism::bluenoise::compareToReference(prism::scene::renderStochasticValues(st, w, h), reference);
        EXPECT_LT(many.rms, 0.6 * one.rms) << sampler;
        if (st.sampler == prism::bluenoise::SamplerKind::White) blurred[0] = one.blurredRms;
        if (st.sampler == prism::bluenoise::SamplerKind::BlueNoise) blurred[1] = one.blurredRms;
    }
    EXPECT_LT(blurred[1], blurred[0]);
}
