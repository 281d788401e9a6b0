// The usage example of prism/water/water_scene.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/water/height_field.hpp"
#include "prism/water/rain_rates.hpp"
// [snippet]
#include "prism/water/water_scene.hpp"
using namespace prism::water;
// [/snippet]

int main() {
    // [snippet]
    WaterSceneDescription d;
    d.terrain = proceduralTerrain({.width = 256, .height = 256});  // default: 512 x 512
    d.rainMmPerHour = rainRateMmPerHour(RainClass::Heavy);
    d.fog = prism::view::Fog{};
    WaterScene scene(std::move(d));
    scene.advance(1.0);  // one second of rain
    auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    WaterSceneRenderer renderer(scene);
    prism::image::Image8 img = renderer.renderImage(overviewCamera(scene.terrain()), 640, 480);
    // [/snippet]
    return img.width == 640 && scene.hasWater() ? 0 : 1;
}
