// The "In code" example of docs/rain.md, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/rain/rain_scene.hpp"

int main() {
    // [snippet]
    auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});  // compute shaders
    prism::rain::RainSceneDesc desc = prism::rain::defaultRainScene();  // ground, sky, sun, lamp, moderate rain
    desc.rain->wind.strength = 5.0f;                                    // m/s, random direction from the seed
    desc.fog = prism::rain::SceneFog{};                                 // distance fog + billboards
    prism::rain::RainScene scene(desc);
    scene.update(1.0f / 60.0f);
    prism::image::Image8 image = scene.render(800, 800);
    // [/snippet]
    return image.width == 800 && scene.fogBillboards() != nullptr ? 0 : 1;
}
