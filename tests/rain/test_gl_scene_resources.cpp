// "Model only what the scene requires": a scene without rain creates no particle
// buffer, runs no update and builds no rain program; without fog no FOG=1 variant and
// no fog billboards exist. Counted with prism::gl's process-wide object and dispatch
// counters (which also count the ground and the frame, so every scene is compared with
// the same scene without rain and fog) and the scene's program list.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "prism/gl/compute.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rain::test {
namespace {

class RainSceneResources : public ::prism::test::GlTest {};

bool anyContains(const std::vector<std::string>& names, const std::string& part) {
    return std::any_of(names.begin(), names.end(),
                       [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

// GL objects created and compute dispatches run while a piece of work ran.
struct Cost {
    std::uint64_t buffers = 0, textures = 0, vertexArrays = 0, dispatches = 0;
    bool operator==(const Cost&) const = default;
};

std::ostream& operator<<(std::ostream& os, const Cost& c) {
    return os << "{buffers " << c.buffers << ", textures " << c.textures << ", vertex arrays " << c.vertexArrays
              << ", dispatches " << c.dispatches << "}";
}

template <class Work>
Cost costOf(Work&& work) {
    using gl::ObjectKind;
    const gl::ObjectCounts before = gl::objectCounts();
    const std::uint64_t dispatches = gl::computeDispatches();
    work();
    const gl::ObjectCounts after = gl::objectCounts();
    const auto made = [&](ObjectKind kind) { return after.created(kind) - before.created(kind); };
    return {made(ObjectKind::Buffer), made(ObjectKind::Texture), made(ObjectKind::VertexArray),
            gl::computeDispatches() - dispatches};
}

Cost minus(const Cost& a, const Cost& b) {
    return {a.buffers - b.buffers, a.textures - b.textures, a.vertexArrays - b.vertexArrays,
            a.dispatches - b.dispatches};
}

constexpr int kSize = 48;

// Builds `desc`, steps it `updates` times, renders one frame and lets `inspect` look at
// the live scene; returns what all that created.
template <class Inspect>
Cost sceneCost(const RainSceneDesc& desc, int updates, Inspect&& inspect) {
    return costOf([&] {
        RainScene scene(desc);
        for (int i = 0; i < updates; ++i) scene.update(1.0f / 30.0f);
        (void)scene.render(kSize, kSize);
        inspect(scene);
    });
}

// The same scene without rain and fog: the ground, the lamp and the frame.
Cost groundCost(RainSceneDesc desc) {
    desc.rain.reset();
    desc.fog.reset();
    return sceneCost(desc, 1, [](RainScene&) {});
}

TEST_F(RainSceneResources, NoRainNoFogBuildsOnlyTheGround) {
    RainSceneDesc desc = defaultRainScene();
    desc.rain.reset();
    desc.fog.reset();
    desc.showLampBulb = false;
    const Cost scene = sceneCost(desc, 3, [](RainScene& s) {
        EXPECT_EQ(s.rain(), nullptr);
        EXPECT_EQ(s.fogBillboards(), nullptr);
        EXPECT_EQ(s.programsInUse(), std::vector<std::string>{"ground (FOG=0)"});
        EXPECT_EQ(s.programs().built(), 1u);
    });
    // Exactly the ground's mesh and the frame render() draws into, built here directly.
    const Cost ground = costOf([&] {
        render::GpuMesh mesh(makeRainGround(desc.ground), suiteResource<RainPrograms>().catalog().contractAttributes);
        gl::Framebuffer frame(kSize, kSize, gl::ColorFormat::Rgba8);
    });
    EXPECT_EQ(scene, ground) << "particle or billboard buffers, streak or noise textures without rain or fog";
    EXPECT_EQ(scene.dispatches, 0u) << "a rain update ran without rain";
}

TEST_F(RainSceneResources, RainWithoutFogHasNoFogVariant) {
    RainSceneDesc desc = defaultRainScene();
    desc.fog.reset();
    const Cost scene = sceneCost(desc, 1, [](RainScene& s) {
        ASSERT_NE(s.rain(), nullptr);
        const std::vector<std::string> expected = {"ground (FOG=0)", "rain_cull (default)", "rain_init (default)",
                                                   "rain_streaks (FOG=0)", "rain_update (default)"};
        EXPECT_EQ(s.programsInUse(), expected);
        EXPECT_FALSE(anyContains(s.programsInUse(), "FOG=1"));
        EXPECT_FALSE(anyContains(s.programsInUse(), "fog_billboards"));
        GLint64 size = 0;
        glBindBuffer(GL_COPY_READ_BUFFER, s.rain()->particleBuffer());
        glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        EXPECT_EQ(static_cast<std::uint64_t>(size),
                  std::uint64_t{s.rain()->capacity()} * RainSystem::kBytesPerParticle);
    });
    // The particle buffer, the culled copy and its draw commands, one streak texture array, the
    // vertex array of the culled particles; one seeding, one update and one culling pass.
    EXPECT_EQ(minus(scene, groundCost(desc)), (Cost{3, 1, 1, 3}));
}

TEST_F(RainSceneResources, FogWithoutRainUsesOnlyFogVariants) {
    RainSceneDesc desc = defaultRainScene();
    desc.rain.reset();
    desc.fog = SceneFog{};
    const Cost scene = sceneCost(desc, 1, [](RainScene& s) {
        EXPECT_EQ(s.rain(), nullptr);
        ASSERT_NE(s.fogBillboards(), nullptr);
        const std::vector<std::string> expected = {"fog_billboards (FOG=1)", "ground (FOG=1)"};
        EXPECT_EQ(s.programsInUse(), expected);
    });
    // The billboard buffer, its noise texture array and vertex array; no dispatch.
    EXPECT_EQ(minus(scene, groundCost(desc)), (Cost{1, 1, 1, 0}));
}

TEST_F(RainSceneResources, DistanceFogWithoutBillboardsBuildsNoBillboards) {
    RainSceneDesc desc = defaultRainScene();
    desc.fog = SceneFog{};
    desc.fog->billboards.strength = 0.0f;
    const Cost scene = sceneCost(desc, 1, [](RainScene& s) {
        EXPECT_EQ(s.fogBillboards(), nullptr);
        const std::vector<std::string> expected = {"ground (FOG=1)", "rain_cull (default)", "rain_init (default)",
                                                   "rain_streaks (FOG=1)", "rain_update (default)"};
        EXPECT_EQ(s.programsInUse(), expected);
    });
    EXPECT_EQ(minus(scene, groundCost(desc)), (Cost{3, 1, 1, 3})) << "the rain's objects only";
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
