// The usage example of prism/water/gpu_water_simulation.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/water/height_field.hpp"
#include "prism/water/rain_rates.hpp"
// [snippet]
#include "prism/water/gpu_water_simulation.hpp"
// [/snippet]

int main() {
    const prism::water::HeightField terrain = prism::water::proceduralTerrain({.width = 64, .height = 64});
    const std::vector<float> permeability = prism::water::proceduralPermeability(terrain);
    const prism::water::WaterParams params;
    const double rate = prism::water::mmPerHourToMetresPerSecond(10.0);
    // [snippet]
    auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    prism::water::GpuWaterSimulation sim(terrain, permeability, params);
    sim.setRainRate(rate);
    sim.advance(0.5);            // dispatches only; no readback
    auto ledger = sim.ledger();  // reads back the depths and the double-precision totals
    // [/snippet]
    return ledger.rainIn > 0.0 && ledger.stored > 0.0 && ledger.stored <= ledger.rainIn ? 0 : 1;
}
