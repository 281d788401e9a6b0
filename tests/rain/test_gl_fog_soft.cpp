// Soft fog billboards: where a billboard dips into the ground the depth test alone cuts
// it along a hard line; fading it out within softDistance above the ground removes the
// line. Measured on the fog's own contribution (image with billboards minus without):
// near the ground it is much weaker with the soft fade than with a hard cut
// (softDistance 0.1 mm), high up in the sky the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "prism/image/png_io.hpp"
#include "prism/rain/rain_scene.hpp"
#include "prism/test/env_flag.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rain {
namespace {

using RainGlTest = ::prism::test::GlTest;

constexpr int kSize = 128;

image::Image8 renderFog(float strength, float softDistance) {
    RainSceneDesc d = defaultRainScene();
    d.camera = rainSceneView(0);
    d.rain.reset();
    SceneFog fog;
    fog.distance.density = 0.0f;  // billboards only
    fog.billboards.strength = strength > 0.0f ? strength : 0.0f;
    fog.billboards.count = 60;
    fog.billboards.minHeight = 0.3f;  // low centres: the 16 m squares reach deep into the ground
    fog.billboards.maxHeight = 1.5f;
    fog.billboards.softDistance = softDistance;
    d.fog = fog;
    RainScene scene(d);
    scene.update(1.0f / 30.0f);
    return scene.render(kSize, kSize);
}

double luminance(const image::Image8& img, int x, int y) {
    const auto p = img.at(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The fog's contribution (|with - without| luminance) summed over rows [y0, y1).
double contribution(const image::Image8& withFog, const image::Image8& without, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < kSize; ++x) sum += std::abs(luminance(withFog, x, y) - luminance(without, x, y));
    return sum;
}

TEST_F(RainGlTest, FogBillboardsFadeSoftlyIntoTheGround) {
    const image::Image8 without = renderFog(0.0f, 1.5f);
    const image::Image8 softImage = renderFog(0.6f, 1.5f), hardImage = renderFog(0.6f, 1e-4f);
    if (::prism::test::envFlag("PRISM_SAVE_ACTUAL")) {
        image::writePng("/tmp/fog-soft.png", softImage);
        image::writePng("/tmp/fog-hard.png", hardImage);
        image::writePng("/tmp/fog-none.png", without);
    }
    // Bottom rows: ground close to the camera, where the billboards pass into it; top
    // rows: sky, seen through billboard parts metres above the ground.
    const double nearGroundSoft = contribution(softImage, without, kSize * 3 / 4, kSize);
    const double nearGroundHard = contribution(hardImage, without, kSize * 3 / 4, kSize);
    const double skySoft = contribution(softImage, without, 0, kSize / 4);
    const double skyHard = contribution(hardImage, without, 0, kSize / 4);
    std::cout << "[fog] billboard contribution near the ground: soft " << nearGroundSoft << ", hard cut "
              << nearGroundHard << "; in the sky: soft " << skySoft << ", hard " << skyHard << "\n";
    ASSERT_GT(nearGroundHard, 0.0) << "the billboards must reach into the ground";
    EXPECT_LT(nearGroundSoft, 0.5 * nearGroundHard) << "fades out where it meets the ground";
    EXPECT_NEAR(skySoft, skyHard, 0.1 * skyHard) << "and nowhere else";
}

}  // namespace
}  // namespace prism::rain
