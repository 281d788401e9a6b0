// The usage example of prism/water/backend_choice.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/water/backend_choice.hpp"
// [/snippet]

int main() {
    // [snippet]
    using namespace prism::water;
    auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    const HeightField t = proceduralTerrain({.width = 128, .height = 128});
    BackendChoice c = chooseFastestBackend(t, proceduralPermeability(t), WaterParams{});
    // c.backend: SimulationBackend::Cpu on llvmpipe (the compute path is 5-9x slower there)
    // [/snippet]
    return c.backend == SimulationBackend::Cpu || c.backend == SimulationBackend::Gpu ? 0 : 1;
}
