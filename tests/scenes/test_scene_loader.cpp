// Scene files: the documented format parses, and malformed scenes give the file, the
// JSON path and what was expected (or file:line:col for syntax errors).
#include <gtest/gtest.h>

#include <variant>

#include "prism/scene/scene_loader.hpp"

using prism::scene::parseScene;
using prism::scene::SceneError;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseScene(text, "scene.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(SceneLoader, ReadsTheExampleScenes) {
    for (const char* name : {"one_light", "four_lights", "fog", "rain", "water", "puddles_closeup"}) {
        auto scene = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/" + name + ".json");
        EXPECT_FALSE(scene.objects.empty()) << name;
        EXPECT_FALSE(scene.lights.directional.empty()) << name;
    }
    auto fog = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/fog.json");
    ASSERT_TRUE(fog.fog.has_value());
    EXPECT_FLOAT_EQ(fog.fog->density, 0.12f);
    auto four = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/four_lights.json");
    EXPECT_EQ(four.lights.directional.size(), 4u);
    EXPECT_EQ(four.lights.points.size(), 1u);
}

TEST(SceneLoader, FullObjectSyntax) {
    auto s = parseScene(R"({
      "camera": {"eye": [1, 2, 3], "target": [0, 0, 0], "fovY": 50, "near": 0.5, "far": 20},
      "lights": [{"type": "ambient", "color": [0.2, 0.2, 0.2]},
                 {"type": "point", "position": [0, 3, 0]}],
      "objects": [{"mesh": "torus", "subdivision": 2,
                   "transform": {"translate": [1, 0, 0], "rotateDegrees": [0, 90, 0], "scale": 2},
                   "material": {"shader": "phong", "color": [1, 0, 0], "shininess": 8, "specular": 0.1,
                                "variant": {"BLINN": "1"}}}],
      "rain": {"intensity": "heavy", "wind": [1, 0, 0]},
      "water": {"grid": 128, "cellSize": 0.5, "seconds": 30, "soilMmPerHour": 2, "seed": 4}
    })",
                        "s.json");
    EXPECT_EQ(s.camera.eye, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(s.lights.ambient.x, 0.2f);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].variantOverrides.front(), std::make_pair(std::string("BLINN"), std::string("1")));
    EXPECT_NEAR(s.objects[0].world[3][0], 1.0f, 1e-6f);
    ASSERT_TRUE(s.rain.has_value());
    EXPECT_EQ(s.rain->intensityClass, prism::rain::RainClass::Heavy);
    ASSERT_TRUE(s.water.has_value());
    EXPECT_EQ(s.water->gridSize, 128u);
    EXPECT_DOUBLE_EQ(s.water->seconds, 30.0);
    EXPECT_DOUBLE_EQ(s.water->soilMillimetresPerHour, 2.0);
}

TEST(SceneLoader, DirectionWithTwoNumbers) {
    EXPECT_EQ(errorOf(R"({"lights": [{"type": "ambient"}, {"type": "ambient"},
                                     {"type": "directional", "direction": [1, 2]}]})"),
              "scene.json: /lights/2/direction: expected 3 numbers");
}

TEST(SceneLoader, MisspelledKeyIsAnError) {
    EXPECT_EQ(errorOf(R"({"fogg": {}})").rfind("scene.json: /fogg: expected no such key here; known keys: camera", 0),
              0u)
        << errorOf(R"({"fogg": {}})");
}

TEST(SceneLoader, WrongTypes) {
    EXPECT_EQ(errorOf(R"({"camera": {"fovY": "wide"}})"), "scene.json: /camera/fovY: expected a number");
    EXPECT_EQ(errorOf(R"({"objects": {"mesh": "sphere"}})"), "scene.json: /objects: expected an array of objects");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shininess": -1}}]})")
                  .rfind("scene.json: /objects/0/material/shininess: expected a number in [0", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"lights": [{"type": "spot"}]})"),
              "scene.json: /lights/0/type: expected ambient, directional or point");
    EXPECT_EQ(errorOf(R"({"rain": {"intensity": "monsoon"}})"),
              "scene.json: /rain/intensity: expected one of drizzle, light, moderate, heavy, excessive, cloudburst");
    EXPECT_EQ(errorOf(R"({"lights": [{"type": "ambient", "color": [1, -1, 0]}]})"),
              "scene.json: /lights/0/color/1: expected a colour component >= 0");
    EXPECT_EQ(errorOf("[]"), "scene.json: /: expected an object");
}

TEST(SceneLoader, DegenerateCameraAndLights) {
    EXPECT_EQ(errorOf(R"({"camera": {"eye": [0, 0, 0], "target": [0, 0, 0]}})"),
              "scene.json: /camera/target: expected a point other than /camera/eye");
    EXPECT_EQ(errorOf(R"({"camera": {"near": 5, "far": 1}})"),
              "scene.json: /camera/far: expected a value greater than /camera/near");
    EXPECT_EQ(errorOf(R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})"),
              "scene.json: /lights/0/direction: expected a non-zero direction");
}

TEST(SceneLoader, SyntaxErrorHasLineAndColumn) {
    auto e = errorOf("{\n  \"camera\": {\n    \"eye\": [0, 0, 1],\n  }\n}\n");
    EXPECT_EQ(e.rfind("scene.json:4:3: syntax error", 0), 0u) << e;
}

TEST(SceneLoader, MissingFile) {
    try {
        prism::scene::loadScene("/nonexistent/scene.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.json: cannot open the scene file; check the path");
    }
}

// Guard rails: an overflowing rain rate is an error at its JSON path, and so is a water
// run whose simulated time needs more substeps than the cap at its cell size.
TEST(SceneLoader, RejectsOverflowingRainAndUnstableWaterRuns) {
    EXPECT_EQ(errorOf(R"({"rain": {"rateMmPerHour": 1e46}})"),
              "scene.json: /rain/rateMmPerHour: expected a number in [0, 10000]");
    EXPECT_EQ(errorOf(R"({"water": {"rainMmPerHour": 1e300}})"),
              "scene.json: /water/rainMmPerHour: expected a number in [0, 10000]");
    const std::string tooLong = errorOf(R"({"water": {"cellSize": 0.001, "seconds": 86400}})");
    EXPECT_EQ(tooLong.rfind("scene.json: /water/seconds: expected a time the water step can take", 0), 0u) << tooLong;
    EXPECT_NE(tooLong.find("c dt / h <= 1/sqrt(2)"), std::string::npos) << tooLong;
    EXPECT_NE(tooLong.find("largest stable substep"), std::string::npos) << tooLong;
}

TEST(SceneLoader, ReadsTheDiffractionScenes) {
    for (const char* name : {"diffraction_cd", "diffraction_grating", "diffraction_snake"}) {
        auto scene = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/" + name + ".json");
        ASSERT_EQ(scene.objects.size(), 1u) << name;
        EXPECT_EQ(scene.objects[0].shader, "diffraction") << name;
        ASSERT_TRUE(scene.objects[0].diffraction.has_value()) << name;
        EXPECT_EQ(scene.objects[0].diffractionPointer, "/objects/0/material/diffraction") << name;
    }
    auto cd = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/diffraction_cd.json");
    EXPECT_EQ(cd.objects[0].diffraction->heightFieldType, "cd");
    EXPECT_TRUE(cd.objects[0].diffraction->radialTangent);
    auto grating = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/diffraction_grating.json");
    const auto& g = *grating.objects[0].diffraction;
    EXPECT_EQ(g.path, 'b');
    EXPECT_EQ(g.tableSize, 256);
    EXPECT_EQ(g.wavelengthStepNm, 10);
    EXPECT_DOUBLE_EQ(std::get<prism::diffraction::GratingParams>(g.heightField).periodNm, 2500.0);
}

TEST(SceneLoader, DiffractionMaterialSyntax) {
    const auto s = parseScene(R"({"objects": [{"mesh": "grid", "material": {"shader": "diffraction",
        "diffraction": {"height_field": {"type": "blazed", "period_nm": 1800, "amplitude_nm": 80},
                        "path": "a", "wavelength_step_nm": 20, "terms": 6, "table_size": 64,
                        "tangent": [0, 0, 1]}}}]})",
                              "dir/scene.json");
    const auto& m = *s.objects[0].diffraction;
    EXPECT_EQ(m.heightFieldType, "blazed");
    EXPECT_EQ(m.path, 'a');
    EXPECT_EQ(m.wavelengthStepNm, 20);
    ASSERT_TRUE(m.terms.has_value());
    EXPECT_EQ(*m.terms, 6);
    EXPECT_EQ(m.tableSize, 64);
    EXPECT_FALSE(m.radialTangent);
    EXPECT_DOUBLE_EQ(m.tangent[2], 1.0);
    // A PNG height field is relative to the scene file.
    const auto png = parseScene(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "png", "file": "h.png", "nm_per_pixel": 50, "height_scale_nm": 100}}}}]})",
                                "dir/scene.json");
    EXPECT_EQ(std::get<prism::diffraction::PngField>(png.objects[0].diffraction->heightField).file, "dir/h.png");
}

TEST(SceneLoader, DiffractionErrorsNameTheJsonPath) {
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction"}}]})"),
              "scene.json: /objects/0/material/diffraction: expected the diffraction parameters (an object with a "
              "height_field; docs/scenes.md)");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "phong", "diffraction": {}}}]})"),
              "scene.json: /objects/0/material/diffraction: expected no diffraction parameters unless \"shader\" is "
              "\"diffraction\"");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "sinusoid", "period_nm": -2500}}}}]})"),
              "scene.json: /objects/0/material/diffraction/height_field/period_nm: expected a number in (0, 1e+09]");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "cd"}, "path": "d"}}}]})"),
              "scene.json: /objects/0/material/diffraction/path: expected \"a\" (per wavelength), \"b\" "
              "(pre-integrated tables) or \"c\" (w volume)");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "cd"}, "wavelength_step_nm": 3}}}]})"),
              "scene.json: /objects/0/material/diffraction/wavelength_step_nm: expected 1, 2, 5, 10 or 20");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "cd"}, "tolerance": 1e-3, "terms": 4}}}]})"),
              "scene.json: /objects/0/material/diffraction/terms: give either tolerance or terms, not both");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "cd"}, "tangent": "spiral"}}}]})"),
              "scene.json: /objects/0/material/diffraction/tangent: expected [x, y, z] or \"radial\"");
    EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shader": "diffraction", "diffraction":
        {"height_field": {"type": "cd"}, "pathh": "b"}}}]})")
                  .rfind("scene.json: /objects/0/material/diffraction/pathh: unknown key", 0),
              0u);
}

// --- "stochastic": the soft-shadow Monte Carlo effect -----------------------------------

TEST(SceneLoader, StochasticExampleAndAbsence) {
    auto s = prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/soft_shadows.json");
    ASSERT_TRUE(s.stochastic.has_value());
    EXPECT_EQ(s.stochastic->sampler, prism::bluenoise::SamplerKind::BlueNoise);
    EXPECT_EQ(s.stochastic->spp, 1);
    EXPECT_EQ(s.stochastic->frame, 0);
    EXPECT_EQ(s.stochastic->frames, 1);
    ASSERT_EQ(s.stochastic->light.spheres.size(), 3u);
    EXPECT_DOUBLE_EQ(s.stochastic->light.spheres[1].z, 0.9);
    EXPECT_DOUBLE_EQ(s.stochastic->light.lightHalfLength, 0.8);
    EXPECT_TRUE(s.objects.empty());
    // A scene without the key has no effect at all.
    EXPECT_FALSE(prism::scene::loadScene(std::string(PRISM_SCENES_DIR) + "/one_light.json").stochastic.has_value());
    EXPECT_FALSE(parseScene("{}", "e.json").stochastic.has_value());
}

TEST(SceneLoader, StochasticFullSyntax) {
    auto s = parseScene(R"({"stochastic": {"sampler": "sorted", "spp": 4, "frames": 16, "extent": 2,
        "light": {"height": 3, "halfLength": 0.5, "halfWidth": 0.2, "radiance": 2},
        "spheres": [{"center": [0, 0, 1], "radius": 0.4}], "mask": {"size": 32, "seed": 7},
        "block": 16, "retargetEpochs": 0}})",
                        "s.json");
    ASSERT_TRUE(s.stochastic);
    const auto& st = *s.stochastic;
    EXPECT_EQ(st.sampler, prism::bluenoise::SamplerKind::Sorted);
    EXPECT_EQ(st.spp, 4);
    EXPECT_EQ(st.frames, 16);
    EXPECT_DOUBLE_EQ(st.light.extent, 2.0);
    EXPECT_DOUBLE_EQ(st.light.lightHeight, 3.0);
    EXPECT_DOUBLE_EQ(st.light.lightHalfWidth, 0.2);
    EXPECT_DOUBLE_EQ(st.light.radiance, 2.0);
    ASSERT_EQ(st.light.spheres.size(), 1u);
    EXPECT_DOUBLE_EQ(st.light.spheres[0].radius, 0.4);
    EXPECT_EQ(st.maskSize, 32);
    EXPECT_EQ(st.maskSeed, 7u);
    EXPECT_EQ(st.block, 16);
    EXPECT_EQ(st.retargetEpochs, 0);
}

TEST(SceneLoader, StochasticErrorsNameTheJsonPath) {
    EXPECT_EQ(errorOf(R"({"stochastic": {"sampler": "pink"}})"),
              "scene.json: /stochastic/sampler: expected white, bluenoise or sorted, not \"pink\"");
    EXPECT_EQ(errorOf(R"({"stochastic": {"spp": 0}})"),
              "scene.json: /stochastic/spp: expected a whole number from 1 to 1024");
    EXPECT_EQ(errorOf(R"({"stochastic": {"frame": 2, "frames": 4}})"),
              "scene.json: /stochastic/frames: expected either frame or frames > 1, not both");
    EXPECT_NE(errorOf(R"({"stochastic": {"spheres": [{"center": [0, 0, 1], "radius": 0.2}, {"center": [0, 0]}]}})")
                  .find("scene.json: /stochastic/spheres/1/center: expected 3 numbers"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"stochastic": {"spheres": [{"center": [0, 0, 5], "radius": 0.2}]}})")
                  .find("/stochastic/spheres/0/center/2"),
              std::string::npos);
    EXPECT_NE(
        errorOf(R"({"stochastic": {"light": {"heigth": 2}}})").find("/stochastic/light/heigth: expected no such key"),
        std::string::npos);
    EXPECT_NE(errorOf(R"({"stochastic": {"effect": "ao"}})").find("/stochastic/effect"), std::string::npos);
    EXPECT_NE(errorOf(R"({"stochastic": {"block": 5}})").find("/stochastic/block: expected 4, 8 or 16"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"stochastic": {"mask": {"size": 0}}})").find("/stochastic/mask/size"), std::string::npos);
    EXPECT_NE(errorOf(R"({"stochastic": 3})").find("/stochastic: expected an object"), std::string::npos);
}

// A number finite as a double but past float's range would become infinity in the scene's
// float fields (fuzz.scene_json found `"eye": [0, 1, 4e94]`): it is an error at its path.
TEST(SceneLoader, NumberPastFloatRangeIsAnError) {
    EXPECT_NE(errorOf(R"({"camera": {"eye": [0, 1, 4e94]}})").find("scene.json: /camera/eye/2: expected a number in"),
              std::string::npos)
        << errorOf(R"({"camera": {"eye": [0, 1, 4e94]}})");
    EXPECT_NE(errorOf(R"({"objects": [{"mesh": "sphere", "scale": -1e39}]})").find("/objects/0/scale"),
              std::string::npos);
    EXPECT_NO_THROW(prism::scene::parseScene(R"({"camera": {"eye": [0, 1, 3e38]}})", "scene.json"));
}
