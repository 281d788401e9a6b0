// The usage example of prism/rain/rain_system.hpp, compiled and run by tests/snippets.
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/rain/rain_programs.hpp"
#include "prism/rain/rain_system.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    prism::gl::Framebuffer target(64, 64);
    target.bind();
    prism::rain::RainParams params;
    params.budget = 4096;
    const prism::view::Camera camera;
    const prism::rain::RainLights lights;
    // [snippet]
    prism::rain::RainPrograms programs;
    prism::rain::RainSystem rain(programs, params, camera.eye);
    rain.update(1.0f / 60.0f, camera.eye);  // compute dispatch
    rain.draw({.camera = camera, .aspect = 1.f, .viewportHeight = 800, .lights = lights});
    std::vector<prism::rain::Particle> ps = rain.readParticles();  // tests
    // [/snippet]
    return ps.size() == rain.particleCount() && !ps.empty() ? 0 : 1;
}
