// A uniform thin film on a tilted terrain, seen from straight above, must look uniform: no
// lattice at the period of the water map's cells (issue 28's dark dots). Measured as the
// luminance amplitude at the cell period (prism/test/look_metrics.hpp). The terrain is a
// plane whose tilt turns along z (h = -0.1 x + 0.05 x z): on an exact plane bilinear and
// per-triangle interpolation agree, so only a terrain with curvature inside a cell can show
// whether the fragment's depth matches the triangles the surface is drawn with.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "prism/test/gl_test.hpp"
#include "prism/test/look_metrics.hpp"
#include "prism/water/water_scene.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

using ThinFilm = ::prism::test::GlTest;

constexpr int kCells = 32;
constexpr float kCell = 0.25f;
constexpr int kImage = 256;

// Falls by `slope` m per m towards +x, and turns by `twist` m per m^2 (h = -slope x + twist x z):
// with twist 0 a plane, where bilinear and per-triangle interpolation agree; otherwise each
// cell's bilinear centre lies twist cell^2 / 4 above the two triangles drawn over it.
HeightField twistedPlane(float slope, float twist) {
    HeightField f = test::tiltedTerrain(kCells, slope, kCell);
    for (int z = 0; z < kCells; ++z)
        for (int x = 0; x < kCells; ++x)
            f.heights[f.index(x, z)] += twist * (static_cast<float>(x) * kCell) * (static_cast<float>(z) * kCell);
    return f;
}

image::Image8 renderDepths(const std::vector<float>& depths, const HeightField& terrain) {
    WaterSceneDescription d;
    d.terrain = terrain;
    d.permeability = uniformPermeability(d.terrain, 0.0);
    d.sky.faceSize = 32;
    // Even a thin film fully drawn and visibly darker than the wet ground, so a hole shows.
    d.look.shoreFadeDepth = 1e-4f;
    d.look.absorption = 300.0f;
    WaterScene scene(std::move(d));
    scene.water()->simulation().setDepth(depths);
    WaterSceneRenderer renderer(scene);
    view::Camera top;
    top.eye = {0.0f, 8.0f, 0.001f};
    top.fovYDegrees = 40.0f;
    return renderer.renderImage(top, kImage, kImage);
}

image::Image8 renderFilm(float film, const HeightField& terrain) {
    return renderDepths(std::vector<float>(terrain.cellCount(), film), terrain);
}

// Mean luminance of the pixels in [x0, x0 + n) x [y0, y0 + n).
double meanLuminance(const image::Image8& img, int x0, int y0, int n) {
    double sum = 0.0;
    for (int y = y0; y < y0 + n; ++y)
        for (int x = x0; x < x0 + n; ++x) sum += prism::test::luminance(img.at(x, y));
    return sum / (n * n);
}

// Cell period in pixels near the image centre: 8 m above the plane's middle, 40 degrees
// of view over 256 pixels.
double cellPeriod() {
    const double metresPerPixel = 2.0 * 8.0 * std::tan(20.0 * 3.14159265358979 / 180.0) / kImage;
    return kCell / metresPerPixel;
}

// Bound 1 level: the fixed shader measures 0.04 here, the old one (depth = level -
// bilinear terrain) 8.6, a bright dot in every cell where the
// film's 0.5 mm is less than the twist's 0.78 mm (0.05 x 0.25^2 / 4) between the two.
TEST_F(ThinFilm, AUniformFilmOnATiltedPlaneShowsNoCellLattice) {
    const image::Image8 img = renderFilm(0.0005f, twistedPlane(0.1f, 0.05f));
    const double p = cellPeriod();
    const double amplitude = prism::test::periodicAmplitude(img, {64, 64, 192, 192}, 0.85 * p, 1.15 * p).lattice();
    std::printf("[thin film] cell period %.2f px, amplitude at it %.3f levels (bound 1)\n", p, amplitude);
    EXPECT_LT(amplitude, 1.0) << "a lattice at the cell period: the film's depth disagrees with its triangles";
}

// One dry cell in the same film on the plain slope: its vertex continues the wet neighbours'
// level only up to its own ground. Before, it took the highest neighbour's level, a whole
// cell's drop (25 mm here) above its ground, and the six triangles round it showed as deep,
// dark water: the 24 px window round it measured 38.0 levels against the film's 43.4; now
// 43.7 (dry ground, no darker than the film), bound 2 levels below the film.
TEST_F(ThinFilm, ADryCellOnASlopeRaisesNoWater) {
    const HeightField plane = twistedPlane(0.1f, 0.0f);
    std::vector<float> depths(plane.cellCount(), 0.0005f);
    depths[plane.index(kCells / 2, kCells / 2)] = 0.0f;
    const image::Image8 img = renderDepths(depths, plane);
    const double spot = meanLuminance(img, kImage / 2 - 12, kImage / 2 - 12, 24);
    const double film = meanLuminance(img, kImage / 2 - 12, kImage / 2 + 40, 24);
    std::printf("[thin film] around the dry cell %.2f, the film %.2f levels\n", spot, film);
    EXPECT_GT(spot, film - 2.0) << "water raised over a dry cell on a slope";
}

}  // namespace
}  // namespace prism::water
