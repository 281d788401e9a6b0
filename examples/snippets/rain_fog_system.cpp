// The usage example of prism/rain/fog_system.hpp, compiled and run by tests/snippets.
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/rain/rain_programs.hpp"
// [snippet]
#include "prism/rain/fog_system.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    prism::gl::Framebuffer target(64, 64);
    target.bind();
    prism::rain::RainPrograms programs;
    const prism::rain::SceneFog sceneFog;
    const prism::view::Camera camera;
    const glm::vec3 wind(1.0f, 0.0f, 0.0f);
    const float dt = 1.0f / 60.0f, aspect = 1.0f, time = 0.5f;
    // [snippet]
    prism::rain::FogSystem fog(programs, sceneFog, camera.eye);
    fog.update(dt, camera.eye, wind);
    fog.draw(camera, aspect, &sceneFog.distance, time);
    // [/snippet]
    return programs.used().size() == 1 ? 0 : 1;
}
