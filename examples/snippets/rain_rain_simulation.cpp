// The usage example of prism/rain/rain_simulation.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/rain/rain_simulation.hpp"
// [/snippet]

int main() {
    prism::rain::RainParams params;
    params.budget = 4096;
    glm::vec3 eye(0.0f, 1.7f, 0.0f);
    bool finite = true;
    auto use = [&](const glm::vec4& p) { finite = finite && std::isfinite(p.x + p.y + p.z); };
    // [snippet]
    prism::rain::CpuRainSimulation sim(params, eye);  // seeds particleCountFor(params)
    sim.step(1.0f / 60.0f, eye);                      // fall, wind, wrap around the camera
    for (const auto& p : sim.particles()) use(p.position);
    // [/snippet]
    return finite && sim.particleCount() > 0 ? 0 : 1;
}
