// The usage example of prism/rain/gl_resources.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/rain/rain_scene.hpp"
// [snippet]
#include "prism/rain/gl_resources.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    // [snippet]
    auto before = prism::rain::glObjectCounts();
    // ... build and render a scene ...
    // [/snippet]
    prism::rain::RainSceneDesc desc = prism::rain::defaultRainScene();
    desc.rain->budget = 2048;
    prism::rain::RainScene scene(desc);
    scene.update(1.0f / 60.0f);
    scene.render(64, 64);
    // [snippet]
    auto after = prism::rain::glObjectCounts();
    std::uint64_t made = after.buffersCreated - before.buffersCreated;   // buffers the rain code made
    // [/snippet]
    return made > 0 ? 0 : 1;
}
