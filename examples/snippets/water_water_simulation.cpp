// The usage example of prism/water/water_simulation.hpp, compiled and run by tests/snippets.
#include <cmath>

#include "prism/water/height_field.hpp"
#include "prism/water/rain_rates.hpp"
// [snippet]
#include "prism/water/water_simulation.hpp"
using namespace prism::water;
// [/snippet]

int main() {
    // [snippet]
    HeightField terrain = proceduralTerrain({.width = 128, .height = 128});
    CpuWaterSimulation sim(terrain, proceduralPermeability(terrain), WaterParams{});
    sim.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Heavy)));
    SubstepPlan plan = sim.advance(0.5);     // 0.5 s, split into plan.count substeps
    std::vector<float> depth = sim.depth();  // metres per cell
    MassLedger l = sim.ledger();             // rain in = stored + infiltrated + lost
    // [/snippet]
    return plan.count >= 1 && depth.size() == terrain.cellCount() && l.rainIn > 0.0 && l.stored <= l.rainIn ? 0 : 1;
}
