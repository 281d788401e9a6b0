// The first CPU water step (single-threaded per-cell loops), kept as the reference the
// fast CpuWaterSimulation must match bit for bit in its depths (test_fast_step.cpp).
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "prism/water/water_simulation.hpp"

namespace prism::water::test {

class ReferenceWaterSimulation final : public WaterSimulation {
  public:
    ReferenceWaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params = {});

    std::vector<glm::vec2> depthPairs() const override;
    std::vector<glm::vec2> edgeVelocities() const override;
    std::string_view backendName() const override { return "cpu-reference"; }

  protected:
    void runSubsteps(const StepConstants& constants, long count) override;
    void resetState(std::span<const glm::vec2> depthPairs) override;
    void lossTotals(double& infiltrated, double& lost) const override;

  private:
    void substep(const StepConstants& k);
    void rainAndInfiltration(const StepConstants& k);
    void tangentialFlowOut(const StepConstants& k);
    void tangentialFlowGather();
    void distributionVelocity(const StepConstants& k);
    void distributionApply(const StepConstants& k);
    void smoothing(const StepConstants& k);
    void swapWater();

    std::vector<float> hi_, lo_, hiOut_, loOut_;
    std::vector<float> qEast_, qSouth_;
    std::vector<float> flowAmount_;
    std::vector<int> flowDirection_;
    std::vector<double> infiltratedStep_;
    std::vector<float> lostStep_;
    double infiltrated_ = 0.0, lost_ = 0.0;
};

}  // namespace prism::water::test
