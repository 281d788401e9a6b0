// "Model only what the scene requires": a scene without rain creates no particle
// buffer, runs no update and builds no rain program; without fog no FOG=1 variant and
// no fog billboards exist. Counted with prism/rain/gl_resources.hpp's counters and the
// scene's program list.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "prism/rain/rain_scene.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rain::test {
namespace {

class RainSceneResources : public ::prism::test::GlTest {};

bool anyContains(const std::vector<std::string>& names, const std::string& part) {
    return std::any_of(names.begin(), names.end(),
                       [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

TEST_F(RainSceneResources, NoRainNoFogBuildsOnlyTheGround) {
    RainSceneDesc desc = defaultRainScene();
    desc.rain.reset();
    desc.fog.reset();
    const auto before = glObjectCounts();
    {
        RainScene scene(desc);
        for (int i = 0; i < 3; ++i) scene.update(1.0f / 30.0f);
        (void)scene.render(48, 48);
        EXPECT_EQ(scene.rain(), nullptr);
        EXPECT_EQ(scene.fogBillboards(), nullptr);
        EXPECT_EQ(scene.programsInUse(), std::vector<std::string>{"ground (FOG=0)"});
        EXPECT_EQ(scene.programs().built(), 1u);
    }
    const auto after = glObjectCounts();
    EXPECT_EQ(after.buffersCreated, before.buffersCreated) << "particle or billboard buffers without rain or fog";
    EXPECT_EQ(after.texturesCreated, before.texturesCreated) << "streak or noise textures without rain or fog";
    EXPECT_EQ(after.vertexArraysCreated, before.vertexArraysCreated);
    EXPECT_EQ(after.computeDispatches, before.computeDispatches) << "a rain update ran without rain";
}

TEST_F(RainSceneResources, RainWithoutFogHasNoFogVariant) {
    RainSceneDesc desc = defaultRainScene();
    desc.fog.reset();
    const auto before = glObjectCounts();
    RainScene scene(desc);
    scene.update(1.0f / 30.0f);
    (void)scene.render(48, 48);
    ASSERT_NE(scene.rain(), nullptr);
    const std::vector<std::string> expected = {"ground (FOG=0)", "rain_init (default)", "rain_streaks (FOG=0)",
                                               "rain_update (default)"};
    EXPECT_EQ(scene.programsInUse(), expected);
    EXPECT_FALSE(anyContains(scene.programsInUse(), "FOG=1"));
    EXPECT_FALSE(anyContains(scene.programsInUse(), "fog_billboards"));
    const auto after = glObjectCounts();
    EXPECT_EQ(after.buffersCreated - before.buffersCreated, 1u) << "one particle buffer";
    EXPECT_EQ(after.texturesCreated - before.texturesCreated, 1u) << "one streak texture array";
    EXPECT_EQ(after.computeDispatches - before.computeDispatches, 2u) << "one seeding and one update";
    EXPECT_EQ(after.bufferBytesLive - before.bufferBytesLive,
              static_cast<std::uint64_t>(scene.rain()->capacity()) * RainSystem::kBytesPerParticle);
}

TEST_F(RainSceneResources, FogWithoutRainUsesOnlyFogVariants) {
    RainSceneDesc desc = defaultRainScene();
    desc.rain.reset();
    desc.fog = SceneFog{};
    const auto before = glObjectCounts();
    RainScene scene(desc);
    scene.update(1.0f / 30.0f);
    (void)scene.render(48, 48);
    EXPECT_EQ(scene.rain(), nullptr);
    ASSERT_NE(scene.fogBillboards(), nullptr);
    const std::vector<std::string> expected = {"fog_billboards (FOG=1)", "ground (FOG=1)"};
    EXPECT_EQ(scene.programsInUse(), expected);
    const auto after = glObjectCounts();
    EXPECT_EQ(after.computeDispatches, before.computeDispatches);
    EXPECT_EQ(after.buffersCreated - before.buffersCreated, 1u) << "the billboard buffer only";
}

TEST_F(RainSceneResources, DistanceFogWithoutBillboardsBuildsNoBillboards) {
    RainSceneDesc desc = defaultRainScene();
    desc.fog = SceneFog{};
    desc.fog->billboards.strength = 0.0f;
    const auto before = glObjectCounts();
    RainScene scene(desc);
    scene.update(1.0f / 30.0f);
    (void)scene.render(48, 48);
    EXPECT_EQ(scene.fogBillboards(), nullptr);
    const std::vector<std::string> expected = {"ground (FOG=1)", "rain_init (default)", "rain_streaks (FOG=1)",
                                               "rain_update (default)"};
    EXPECT_EQ(scene.programsInUse(), expected);
    EXPECT_EQ(glObjectCounts().buffersCreated - before.buffersCreated, 1u);
}

TEST_F(RainSceneResources, BadSceneParametersAreClearErrors) {
    RainSceneDesc desc = defaultRainScene();
    desc.rain->intensity = -1.0f;
    EXPECT_THROW(RainScene{desc}, RainParameterError);
    desc = defaultRainScene();
    desc.rain->wind.strength = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(RainScene{desc}, RainParameterError);
    desc = defaultRainScene();
    desc.fog = SceneFog{};
    desc.fog->billboards.strength = 2.0f;
    EXPECT_THROW(RainScene{desc}, RainParameterError);
}

}  // namespace
}  // namespace prism::rain::test
