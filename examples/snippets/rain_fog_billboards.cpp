// The usage example of prism/rain/fog_billboards.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/rain/fog_billboards.hpp"
// [/snippet]

int main() {
    const glm::vec3 eye(0.0f, 1.7f, 0.0f), wind(2.0f, 0.0f, 0.0f);
    const float dt = 1.0f / 60.0f;
    // [snippet]
    prism::rain::SceneFog fog;       // distance fog + billboards
    fog.billboards.strength = 0.5f;  // 0: distance fog only, no billboards
    prism::rain::FogNoiseArray noise = prism::rain::generateFogNoise(64, 16, 7);
    prism::rain::FogBillboardSimulation sim(fog.billboards, eye);
    sim.step(dt, eye, wind);
    // [/snippet]
    return noise.texels.size() == 64u * 64u * 16u && sim.billboards().size() == 40 ? 0 : 1;
}
