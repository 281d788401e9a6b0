// The usage example of prism/rain/rain_scene.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/rain/rain_scene.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    // [snippet]
    prism::rain::RainSceneDesc desc = prism::rain::defaultRainScene();
    desc.rain->wind.strength = 5.0f;
    prism::rain::RainScene scene(desc);  // needs a current GL context (4.3 with rain)
    scene.update(1.0f / 60.0f);          // rain and fog billboards
    prism::image::Image8 image = scene.render(200, 200);
    // [/snippet]
    return image.width == 200 && scene.rain() != nullptr ? 0 : 1;
}
