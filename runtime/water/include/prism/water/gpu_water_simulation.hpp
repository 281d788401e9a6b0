// The water step on the GPU: the compute shaders of shader_sources/water/ (compiled by
// prism-shaderc into prism/water_shaders.hpp) over shader storage buffers, ping-ponging
// the compensated water depths between two buffers. Same step, same fp32 operations
// and order as CpuWaterSimulation (see water_simulation.hpp).
//
// Usage (snippet: examples/snippets/water_gpu_water_simulation.cpp):
//
//     #include "prism/water/gpu_water_simulation.hpp"
//     auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
//     prism::water::GpuWaterSimulation sim(terrain, permeability, params);
//     sim.setRainRate(rate);
//     sim.advance(0.5);            // dispatches only; no readback
//     auto ledger = sim.ledger();  // reads back the depths and the double-precision totals
//
// Mass ledger: each cell accumulates what it infiltrated and lost through the border in
// double precision; ledger() reduces those on the GPU (water_ledger_partial.comp,
// water_ledger_total.comp) and sums the stored water from a readback, in double.
//
// Needs a current GL 4.3+ context (compute shaders, SSBOs, fp64); construction throws
// prism::gl::ContextError otherwise. GL objects die with it (not copyable).
#pragma once

#include <cstddef>
#include <memory>

#include "prism/water/water_simulation.hpp"

namespace prism::water {

class GpuWaterSimulation final : public WaterSimulation {
  public:
    GpuWaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params = {});
    ~GpuWaterSimulation() override;

    // Whether the current context can run it (GL 4.3 or newer).
    static bool isSupported();

    std::vector<glm::vec2> depthPairs() const override;
    std::vector<glm::vec2> edgeVelocities() const override;
    std::string_view backendName() const override { return "gpu"; }
    // Copies the compensated depths into an RG32F texture of the grid's size on the GPU.
    void uploadDepthTexture(unsigned texture) const;

    // The storage buffer that holds the current (hi, lo) depth pairs.
    unsigned depthBuffer() const;
    // Blocks until the GPU has finished every dispatched pass (for timing).
    void finish() const;
    std::size_t programCount() const;

  protected:
    void runSubsteps(const StepConstants& constants, long count) override;
    void resetState(std::span<const glm::vec2> depthPairs) override;
    void lossTotals(double& infiltrated, double& lost) const override;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace prism::water
