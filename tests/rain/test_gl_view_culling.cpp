// What the view needs and nothing else (issue 40): the culling pass (rain_cull.comp) leaves every pixel of
// every technique as it was while it drops the particles outside the view; the update's narrower stores
// still agree with the CPU reference when the fall speed changes; and the level-of-detail weight keeps
// the time-averaged light of the rain layer.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/rain/rain_system.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rain::test {
namespace {

class RainViewCulling : public ::prism::test::GlTest {};

RainParams sceneRain(std::uint32_t seed) {
    RainParams p;
    p.seed = seed;
    p.wind.strength = 4.0f;
    return p;
}

// The rain layer alone: on black, into a float target, summed over `frames` steps of 0.1 s (mean of R, G, B).
double summedLight(RainPrograms& programs, const RainParams& p, int frames, int size) {
    const view::Camera camera = rainSceneView(0);
    RainSystem rain(programs, p, camera.eye);
    gl::Framebuffer fb(size, size, gl::ColorFormat::Rgba32F);
    RainDrawInputs in;
    in.camera = camera;
    in.viewportHeight = size;
    double light = 0.0;
    for (int f = 0; f < frames; ++f) {
        rain.update(0.1f, camera.eye);
        fb.clear({0.0f, 0.0f, 0.0f, 0.0f});
        rain.draw(in);
        const image::ImageF img = fb.readImageF();
        for (std::size_t i = 0; i < img.data.size(); i += 4) light += (img.data[i] + img.data[i + 1] + img.data[i + 2]);
    }
    return light / 3.0;
}

TEST_F(RainViewCulling, CulledDrawsArePixelIdenticalAndSkipTheParticlesOutsideTheView) {
    const view::Camera camera = rainSceneView(0);
    RainSystem rain(suiteResource<RainPrograms>(), sceneRain(2013), camera.eye);
    for (int i = 0; i < 10; ++i) rain.update(1.0f / 30.0f, camera.eye);
    gl::Framebuffer fb(160, 160);
    RainDrawInputs in;
    in.camera = camera;
    in.viewportHeight = 160;
    for (StreakTechnique t :
         {StreakTechnique::GeometryShader, StreakTechnique::Instanced, StreakTechnique::PointSprites}) {
        in.technique = t;
        in.cullToView = false;
        fb.clear({0.33f, 0.36f, 0.42f, 1.0f});
        rain.draw(in);
        const image::Image8 all = fb.readImage8();
        in.cullToView = true;
        fb.clear({0.33f, 0.36f, 0.42f, 1.0f});
        rain.draw(in);
        const image::Image8 culled = fb.readImage8();
        ASSERT_EQ(all.data.size(), culled.data.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < all.data.size(); ++i) differing += all.data[i] != culled.data[i];
        EXPECT_EQ(differing, 0u) << techniqueName(t) << ": channels that differ with the culling";
    }
    const std::uint32_t visible = rain.visibleCount();
    std::cout << "[ info ] view 0 keeps " << visible << " of " << rain.particleCount() << " particles\n";
    EXPECT_GT(visible, 0u);
    EXPECT_LT(visible, rain.particleCount() / 2);  // a 60 deg view of a cylinder around the eye
}

TEST_F(RainViewCulling, UpdateAgreesWithTheCpuReferenceWhenTheFallSpeedChanges) {
    RainParams p;
    p.fixedCount = 8192;
    p.seed = 5;
    const glm::vec3 eye(0.0f, 1.7f, 0.0f);
    RainSystem gpu(suiteResource<RainPrograms>(), p, eye);
    CpuRainSimulation cpu(p, eye);
    for (int i = 0; i < 150; ++i) {
        if (i == 30) {  // respawned drops now fall at the cloudburst's speed
            gpu.setIntensity(rainClassInfo(RainClass::Cloudburst).intensity);
            cpu.setIntensity(rainClassInfo(RainClass::Cloudburst).intensity);
        }
        gpu.update(1.0f / 30.0f, eye);
        cpu.step(1.0f / 30.0f, eye);
    }
    const auto g = gpu.readParticles();
    const auto c = cpu.particles();
    ASSERT_EQ(g.size(), c.size());
    std::size_t speedMismatch = 0;
    for (std::size_t i = 0; i < g.size(); ++i)
        if (std::abs(g[i].velocity.y - c[i].velocity.y) > 1e-4f) ++speedMismatch;
    EXPECT_EQ(speedMismatch, 0u);
}

TEST_F(RainViewCulling, LevelOfDetailKeepsTheTimeAveragedLight) {
    RainParams none = sceneRain(31);
    none.particlesPerDrop = 0.025f;
    none.lodRings = 1;
    RainParams rings = none;
    rings.lodRings = 4;
    rings.lodFalloff = 0.5f;
    auto& programs = suiteResource<RainPrograms>();
    const double reference = summedLight(programs, none, 12, 96);
    const double thinned = summedLight(programs, rings, 12, 96);
    const double bias = thinned / reference - 1.0;
    std::cout << "[ info ] LOD 4 x 0.5 against no LOD: light " << bias * 100.0 << " %\n";
    EXPECT_LT(std::abs(bias), 0.08);  // without the weight: about -42 %
}

}  // namespace
}  // namespace prism::rain::test
