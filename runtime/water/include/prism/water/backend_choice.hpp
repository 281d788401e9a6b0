// Which water step a scene runs, the CPU one or the compute shaders, picked by what is
// faster on the current renderer: measured once per process for each renderer and grid
// size (a few substeps of each on the scene's own terrain), then reused.
//
// Usage (snippet: examples/snippets/water_backend_choice.cpp):
//
//     #include "prism/water/backend_choice.hpp"
//     using namespace prism::water;
//     auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
//     const HeightField t = proceduralTerrain({.width = 128, .height = 128});
//     BackendChoice c = chooseFastestBackend(t, proceduralPermeability(t), WaterParams{});
//     // c.backend: SimulationBackend::Cpu on llvmpipe (the compute path is 5-9x slower there)
//
// Without a GL 4.3 context (no compute shaders) the choice is the CPU step, unmeasured.
#pragma once

#include <string>
#include <vector>

#include "prism/water/height_field.hpp"
#include "prism/water/water_simulation.hpp"

namespace prism::water {

struct BackendChoice {
    SimulationBackend backend = SimulationBackend::Cpu;  // Cpu or Gpu
    double cpuMsPerSubstep = 0.0;                        // median of the measured substeps
    double gpuMsPerSubstep = 0.0;                        // 0 when compute shaders are unavailable
    std::string renderer;                                // GL_RENDERER it was measured on
    bool fromCache = false;                              // true when an earlier measurement was reused
};

// Needs a current GL context (any version); measures at most once per (renderer, width,
// height) in this process.
BackendChoice chooseFastestBackend(const HeightField& terrain, const std::vector<float>& permeability,
                                   const WaterParams& params);

}  // namespace prism::water
