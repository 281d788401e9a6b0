// The water map with its rain and ripple clock, on the CPU or the compute step (see
// prism/water/water_scene.hpp, WaterSystem).
#include "prism/water/water_scene.hpp"

#include <cmath>
#include <stdexcept>

#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"

namespace prism::water {

WaterSystem::WaterSystem(const HeightField& terrain, std::vector<float> permeability, const WaterParams& params,
                         SimulationBackend backend, double rainMmPerHour) {
    if (backend == SimulationBackend::Fastest) backend = chooseFastestBackend(terrain, permeability, params).backend;
    if (backend == SimulationBackend::Gpu)
        simulation_ = std::make_unique<GpuWaterSimulation>(terrain, std::move(permeability), params);
    else
        simulation_ = std::make_unique<CpuWaterSimulation>(terrain, std::move(permeability), params);
    setRain(rainMmPerHour);
}

void WaterSystem::setRain(double mmPerHour) {
    if (!(mmPerHour >= 0.0) || !std::isfinite(mmPerHour))
        throw std::invalid_argument("WaterSystem: the rain rate must be a finite number of mm/h >= 0");
    rainMmPerHour_ = mmPerHour;
    simulation_->setRainRate(mmPerHourToMetresPerSecond(mmPerHour));
}

SubstepPlan WaterSystem::advance(double dt) {
    const SubstepPlan plan = simulation_->advance(dt);
    rippleFrame_ = std::fmod(rippleFrame_ + dt * rippleFramesPerSecond(rainMmPerHour_), RippleFrames::kFrames);
    return plan;
}

}  // namespace prism::water
