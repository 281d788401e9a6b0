// GPU extremes, all without NaN or lost particles: no drops at all, 2^22 drops (one
// seeding + one update, read back), no wind and a gale, a teleport, dt of 0 and a huge
// dt; and the streak drawing of every technique stays finite.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

#include "prism/gl/compute.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/rain/rain_system.hpp"
#include "prism/test/gl_test.hpp"
#include "rain_test_checks.hpp"

namespace prism::rain::test {
namespace {

class GpuRainExtremes : public ::prism::test::GlTest {};

TEST_F(GpuRainExtremes, ZeroParticlesAllocateNothing) {
    RainParams p;
    p.intensity = 0.0f;
    gl::Framebuffer fb(32, 32);
    const auto before = gl::objectCounts();
    const auto dispatchesBefore = gl::computeDispatches();
    RainSystem rain(suiteResource<RainPrograms>(), p, glm::vec3(0.0f));
    rain.update(1.0f / 60.0f, glm::vec3(10.0f));
    fb.clear({0.f, 0.f, 0.f, 1.f});
    rain.draw(RainDrawInputs{});
    EXPECT_EQ(rain.particleCount(), 0u);
    EXPECT_TRUE(rain.readParticles().empty());
    const auto after = gl::objectCounts();
    for (auto kind : {gl::ObjectKind::Buffer, gl::ObjectKind::Texture, gl::ObjectKind::VertexArray})
        EXPECT_EQ(after.created(kind), before.created(kind)) << "object kind " << static_cast<int>(kind);
    EXPECT_EQ(gl::computeDispatches(), dispatchesBefore);
    // Rain starts when the intensity rises.
    rain.setIntensity(rainClassInfo(RainClass::Light).intensity);
    EXPECT_GT(rain.particleCount(), 0u);
    rain.update(1.0f / 60.0f, glm::vec3(10.0f));
    EXPECT_TRUE(allFiniteAndInside(rain.readParticles(), rain.center(), p.radius, p.height));
}

TEST_F(GpuRainExtremes, FourMillionParticlesRunOneUpdate) {
    RainParams p;
    p.fixedCount = 1u << 22;
    p.wind.strength = 4.0f;
    const auto t0 = std::chrono::steady_clock::now();
    RainSystem rain(suiteResource<RainPrograms>(), p, glm::vec3(0.0f, 1.7f, 0.0f));
    rain.update(1.0f / 60.0f, glm::vec3(1.0f, 1.7f, 0.0f));
    const auto g = rain.readParticles();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(g.size(), 1u << 22);
    EXPECT_EQ(rain.gpuBytes(), (std::size_t{1} << 22) * 48u);  // no texture before the first draw
    EXPECT_TRUE(allFiniteAndInside(g, rain.center(), p.radius, p.height));
    std::cout << "[ info ] 2^22 particles: seed + update + read back " << s << " s\n";
}

TEST_F(GpuRainExtremes, NoWindAndAGale) {
    for (float wind : {0.0f, 80.0f, 1000.0f}) {
        RainParams p;
        p.fixedCount = 20000;
        p.wind.strength = wind;
        RainSystem rain(suiteResource<RainPrograms>(), p, glm::vec3(0.0f));
        for (int i = 0; i < 60; ++i) rain.update(1.0f / 30.0f, glm::vec3(0.0f, 0.0f, 0.05f * i));
        EXPECT_TRUE(allFiniteAndInside(rain.readParticles(), rain.center(), p.radius, p.height)) << "wind " << wind;
    }
}

TEST_F(GpuRainExtremes, TeleportAndZeroAndHugeSteps) {
    RainParams p;
    p.fixedCount = 20000;
    p.wind.strength = 5.0f;
    RainSystem rain(suiteResource<RainPrograms>(), p, glm::vec3(0.0f));
    const auto start = rain.readParticles();
    rain.update(0.0f, glm::vec3(0.0f));
    const auto still = rain.readParticles();
    for (std::size_t i = 0; i < still.size(); ++i) ASSERT_EQ(still[i].position, start[i].position) << i;
    const struct {
        float dt;
        glm::vec3 eye;
    } steps[] = {{1e9f, glm::vec3(0.0f)},
                 {std::numeric_limits<float>::infinity(), glm::vec3(0.0f)},
                 {1.0f / 60.0f, glm::vec3(25000.0f, 30.0f, -7000.0f)},
                 {0.0f, glm::vec3(-25000.0f, 0.0f, 0.0f)},
                 {1e-30f, glm::vec3(-25000.0f, 0.0f, 0.0f)}};
    for (const auto& s : steps) {
        rain.update(s.dt, s.eye);
        ASSERT_TRUE(allFiniteAndInside(rain.readParticles(), rain.center(), p.radius, p.height))
            << "dt " << s.dt << ", eye x " << s.eye.x;
    }
    EXPECT_THROW(rain.update(-1.0f, glm::vec3(0.0f)), RainParameterError);
    EXPECT_THROW(rain.update(0.1f, glm::vec3(std::numeric_limits<float>::quiet_NaN())), RainParameterError);
    EXPECT_THROW(rain.setIntensity(-1.0f), RainParameterError);
    EXPECT_THROW(rain.setWind(WindParams{std::nullopt, std::numeric_limits<float>::quiet_NaN()}), RainParameterError);
    EXPECT_TRUE(std::isfinite(rain.params().wind.strength)) << "a refused wind replaced the old one";
    EXPECT_TRUE(std::isfinite(rain.params().intensity)) << "a refused intensity was kept";
    EXPECT_THROW(RainSystem(
                     suiteResource<RainPrograms>(),
                     [] {
                         RainParams q;
                         q.intensity = -3.0f;
                         return q;
                     }(),
                     glm::vec3(0.0f)),
                 RainParameterError);
}

TEST_F(GpuRainExtremes, EveryTechniqueDrawsFinitePixels) {
    RainParams p;
    p.fixedCount = 20000;
    p.wind.strength = 500.0f;  // extreme tilt
    view::Camera cam;
    cam.eye = {0.0f, 1.7f, 0.0f};
    cam.target = {0.0f, 30.0f, 0.001f};  // straight up, along the fall: degenerate streak frames
    RainSystem rain(suiteResource<RainPrograms>(), p, cam.eye);
    rain.update(1.0f / 30.0f, cam.eye);
    for (StreakTechnique t :
         {StreakTechnique::GeometryShader, StreakTechnique::Instanced, StreakTechnique::PointSprites}) {
        gl::Framebuffer fb(64, 64, gl::ColorFormat::Rgba32F);
        fb.clear({0.f, 0.f, 0.f, 1.f});
        RainDrawInputs in;
        in.camera = cam;
        in.viewportHeight = 64;
        in.technique = t;
        rain.draw(in);
        const image::ImageF img = fb.readImageF();
        EXPECT_EQ(image::countNonFinite(img), 0u) << techniqueName(t);
        double sum = 0.0;
        for (float v : img.data) sum += v;
        EXPECT_GT(sum, 64.0 * 64.0 * 1.0 + 1.0) << techniqueName(t) << " drew nothing";
    }
}

}  // namespace
}  // namespace prism::rain::test
