// Unit tests of the viewer's named parameters (viewer_actions.hpp): the streak technique, the
// rain class and the water step are parsed once, here, into the scene's enums, and a bad
// name is refused before it reaches the scene. No window, no context.
#include <gtest/gtest.h>

#include <stdexcept>

#include "viewer_actions.hpp"

namespace {

using prism::viewer::setParameter;
using prism::viewer::ViewerState;

ViewerState withWaterScene() {
    ViewerState state;
    prism::viewer::openScene(state, PRISM_SOURCE_DIR "/examples/scenes/water.json");
    return state;
}

TEST(ViewerActions, RainTechniqueBecomesTheEnum) {
    ViewerState state = withWaterScene();
    auto& rain = *state.scene.scene.rain;
    setParameter(state, "rain.technique", "points");
    EXPECT_EQ(rain.technique, prism::rain::StreakTechnique::PointSprites);
    setParameter(state, "rain.technique", "instanced-quads");
    EXPECT_EQ(rain.technique, prism::rain::StreakTechnique::Instanced);
    EXPECT_THROW(setParameter(state, "rain.technique", "splines"), std::invalid_argument);
    EXPECT_EQ(rain.technique, prism::rain::StreakTechnique::Instanced) << "a refused name changes nothing";
}

TEST(ViewerActions, RainClassBecomesTheEnumAndReplacesTheRate) {
    ViewerState state = withWaterScene();
    auto& rain = *state.scene.scene.rain;
    rain.rateMillimetresPerHour = 12.0;
    setParameter(state, "rain.intensity", "cloudburst");
    EXPECT_EQ(rain.intensityClass, prism::rain::RainClass::Cloudburst);
    EXPECT_FALSE(rain.rateMillimetresPerHour.has_value());
    EXPECT_THROW(setParameter(state, "rain.intensity", "monsoon"), std::invalid_argument);
    EXPECT_EQ(rain.intensityClass, prism::rain::RainClass::Cloudburst);
}

TEST(ViewerActions, WaterStepBecomesTheEnum) {
    ViewerState state = withWaterScene();
    auto& water = *state.scene.scene.water;
    EXPECT_EQ(water.backend, prism::water::SimulationBackend::Fastest);
    setParameter(state, "water.backend", "gpu");
    EXPECT_EQ(water.backend, prism::water::SimulationBackend::Gpu);
    setParameter(state, "water.backend", "cpu");
    EXPECT_EQ(water.backend, prism::water::SimulationBackend::Cpu);
    EXPECT_THROW(setParameter(state, "water.backend", "warp"), std::invalid_argument);
    EXPECT_EQ(water.backend, prism::water::SimulationBackend::Cpu);
}

// Each group has its setter; a name no setter knows is an error, in a group or outside one.
TEST(ViewerActions, UnknownNamesAreRefused) {
    ViewerState state = withWaterScene();
    for (const char* name : {"rain.colour", "water.depth", "lights.point", "fog.height", "material.roughness",
                             "bluenoise.mask", "shadows"})
        EXPECT_THROW(setParameter(state, name, "1"), std::invalid_argument) << name;
    setParameter(state, "lights.directional", "3");
    EXPECT_EQ(state.scene.scene.lights.directional.size(), 3u);
}

}  // namespace
