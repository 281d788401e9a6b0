// How the water looks, measured on rendered images (gl tier): thin films darken the
// ground smoothly from the first tenth of a millimetre (no draw threshold), puddles
// mirror the sky brightly at grazing angles, and shallow water shows the ground under it
// while deep water hides it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "prism/gl/gl_context.hpp"
#include "prism/water/water_scene.hpp"
#include "prism/test/gl_test.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

using WaterGlTest = ::prism::test::GlTest;

constexpr int kSize = 64;

// Mean luminance (0..1) of the pixels in [x0, x1) x [y0, y1).
double meanLuminance(const image::Image8& img, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const auto p = img.at(x, y);
            sum += (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
        }
    return sum / ((x1 - x0) * (y1 - y0));
}

WaterSceneDescription flatScene(std::vector<float> permeability = {}) {
    WaterSceneDescription d;
    d.terrain = test::flatTerrain(32, 32, 0.0f, 0.25f);
    d.permeability = permeability.empty() ? uniformPermeability(d.terrain, 0.0) : std::move(permeability);
    d.rainMmPerHour = 0.0;  // no ripples: the surface is flat
    d.sky.faceSize = 32;
    return d;
}

image::Image8 renderWithDepth(WaterSceneDescription d, float depth, const view::Camera& camera) {
    WaterScene scene(std::move(d));
    scene.water()->simulation().setDepth(std::vector<float>(scene.terrain().cellCount(), depth));
    WaterSceneRenderer renderer(scene);
    return renderer.renderImage(camera, kSize, kSize);
}

view::Camera topDown() {
    view::Camera c;
    c.eye = {0.0f, 6.0f, 0.01f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.fovYDegrees = 40.0f;
    return c;
}

TEST_F(WaterGlTest, ThinFilmsDarkenTheGroundSmoothly) {
    const float films[] = {0.0f, 1e-4f, 3e-4f, 6e-4f, 1e-3f, 2e-3f};
    std::vector<double> lum;
    for (float d : films) lum.push_back(meanLuminance(renderWithDepth(flatScene(), d, topDown()), 16, 16, 48, 48));
    const double range = lum.front() - lum.back();
    ASSERT_GT(range, 0.02) << "a 2 mm film darkens the ground";
    for (std::size_t i = 1; i < lum.size(); ++i) {
        EXPECT_LT(lum[i], lum[i - 1]) << films[i] << " m of water darkens more than " << films[i - 1] << " m";
        EXPECT_LT(lum[i - 1] - lum[i], 0.45 * range) << "no step between " << films[i - 1] << " and " << films[i];
    }
}

TEST_F(WaterGlTest, PuddlesMirrorTheSkyBrightlyAtGrazingAngles) {
    view::Camera grazing;
    grazing.eye = {0.0f, 0.3f, 3.5f};
    grazing.target = {0.0f, 0.0f, -2.0f};  // about 5 degrees above the water
    grazing.fovYDegrees = 40.0f;
    const double steepWater = meanLuminance(renderWithDepth(flatScene(), 0.05f, topDown()), 16, 16, 48, 48);
    // Rows 33-40 see the water 4-7 m away, 2.5-4 degrees above its surface.
    const double grazingWater = meanLuminance(renderWithDepth(flatScene(), 0.05f, grazing), 16, 33, 48, 40);
    const double grazingDry = meanLuminance(renderWithDepth(flatScene(), 0.0f, grazing), 16, 33, 48, 40);
    EXPECT_GT(grazingWater, steepWater + 0.15) << "Fresnel: the sky at grazing angles";
    EXPECT_GT(grazingWater, grazingDry + 0.15) << "the puddle is brighter than the ground around it";
}

// Half the ground compacted (greyer albedo), half loose soil: the two halves stay
// distinct under 2 cm of water and nearly merge under 1.5 m.
TEST_F(WaterGlTest, ShallowWaterShowsTheGroundAndDeepWaterHidesIt) {
    const HeightField t = test::flatTerrain(32, 32, 0.0f, 0.25f);
    std::vector<float> k(t.cellCount());
    for (int z = 0; z < t.height; ++z)
        for (int x = 0; x < t.width; ++x) k[t.index(x, z)] = x < 16 ? 0.0f : 1e-2f;
    auto contrast = [&](float depth) {
        const image::Image8 img = renderWithDepth(flatScene(k), depth, topDown());
        return std::abs(meanLuminance(img, 12, 20, 28, 44) - meanLuminance(img, 36, 20, 52, 44));
    };
    const double dry = contrast(0.0f), shallow = contrast(0.02f), deep = contrast(1.5f);
    ASSERT_GT(dry, 0.01) << "the two halves must differ on dry ground";
    EXPECT_GT(shallow, 0.5 * dry) << "2 cm of clear water shows the ground";
    EXPECT_LT(deep, 0.25 * dry) << "1.5 m of water hides it";
}

}  // namespace
}  // namespace prism::water
