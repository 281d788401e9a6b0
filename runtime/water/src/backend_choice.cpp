// Measuring the CPU and compute-shader water steps once and picking the faster (see
// prism/water/backend_choice.hpp).
#include "prism/water/backend_choice.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>
#include <tuple>

#include "prism/gl/gl.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"

namespace prism::water {
namespace {

constexpr int kWarmup = 2;
constexpr int kTimed = 5;

double medianMsPerSubstep(WaterSimulation& sim, bool gpu) {
    const double dt = maxStableDt(sim.params(), sim.terrain().cellSize);
    sim.setRainRate(mmPerHourToMetresPerSecond(100.0));
    for (int i = 0; i < kWarmup; ++i) sim.advance(dt);
    if (gpu) glFinish();
    std::vector<double> ms;
    for (int i = 0; i < kTimed; ++i) {
        const auto start = std::chrono::steady_clock::now();
        sim.advance(dt);
        if (gpu) glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

}  // namespace

BackendChoice chooseFastestBackend(const HeightField& terrain, const std::vector<float>& permeability,
                                   const WaterParams& params) {
    static std::mutex mutex;
    static std::map<std::tuple<std::string, int, int>, BackendChoice> cache;
    const GLubyte* name = glGetString(GL_RENDERER);
    BackendChoice choice;
    choice.renderer = name ? reinterpret_cast<const char*>(name) : "unknown";
    const auto key = std::make_tuple(choice.renderer, terrain.width, terrain.height);
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (auto it = cache.find(key); it != cache.end()) {
            BackendChoice cached = it->second;
            cached.fromCache = true;
            return cached;
        }
    }
    {
        CpuWaterSimulation cpu(terrain, permeability, params);
        choice.cpuMsPerSubstep = medianMsPerSubstep(cpu, false);
    }
    try {
        GpuWaterSimulation gpu(terrain, permeability, params);
        choice.gpuMsPerSubstep = medianMsPerSubstep(gpu, true);
    } catch (const std::exception&) {
        choice.gpuMsPerSubstep = 0.0;  // no GL 4.3 compute shaders here
    }
    choice.backend = choice.gpuMsPerSubstep > 0.0 && choice.gpuMsPerSubstep < choice.cpuMsPerSubstep
                         ? SimulationBackend::Gpu
                         : SimulationBackend::Cpu;
    std::lock_guard<std::mutex> lock(mutex);
    cache.emplace(key, choice);
    return choice;
}

}  // namespace prism::water
