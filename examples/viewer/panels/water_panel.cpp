// Water panel (open scene with water): simulation running or paused, step, reset, and the
// rain coupling (rain-fed from the scene's rain, or a fixed rate), and the CPU or GPU step.
#include <imgui.h>

#include <string>

#include "prism/water/water_simulation.hpp"

#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

void drawWaterPanel(ViewerState& state) {
    if (!panelHeader("Water", state, state.scene.open && state.scene.scene.water.has_value())) return;
    if (!state.scene.open || !state.scene.scene.water) {
        ImGui::TextDisabled("open a scene with water (water.json)");
        return;
    }
    auto& view = state.scene;
    auto& w = *view.scene.water;
    ImGui::Checkbox("running", &view.waterRunning);
    float step = static_cast<float>(view.waterStepSeconds);
    if (ImGui::SliderFloat("step (s)", &step, 0.5f, 60.0f, "%.1f")) view.waterStepSeconds = step;
    if (ImGui::Button("step")) {
        w.seconds += view.waterStepSeconds;
        view.dirty = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("reset")) {
        w.seconds = view.waterStartSeconds;
        view.dirty = true;
    }
    ImGui::Text("simulated: %.1f s of rain", w.seconds);
    bool rainFed = view.scene.rain.has_value();
    if (ImGui::Checkbox("rain-fed (scene rain)", &rainFed)) setParameter(state, "rain.enabled", rainFed ? "1" : "0");
    if (!rainFed) {
        float rate = static_cast<float>(w.rainRateMillimetresPerHour);
        if (ImGui::SliderFloat("rate (mm/h)", &rate, 0.0f, 100.0f)) {
            w.rainRateMillimetresPerHour = rate;
            view.dirty = true;
        }
    }
    float soil = static_cast<float>(w.soilMillimetresPerHour);
    if (ImGui::SliderFloat("soil (mm/h)", &soil, 0.0f, 50.0f)) {
        w.soilMillimetresPerHour = soil;
        view.dirty = true;
    }
    using water::SimulationBackend;
    const std::string backend(water::simulationBackendName(w.backend));
    if (ImGui::BeginCombo("step on", backend.c_str())) {
        for (SimulationBackend b : {SimulationBackend::Fastest, SimulationBackend::Cpu, SimulationBackend::Gpu}) {
            const std::string name(water::simulationBackendName(b));
            if (ImGui::Selectable(name.c_str(), w.backend == b)) setParameter(state, "water.backend", name);
        }
        ImGui::EndCombo();
    }
    if (w.backend == SimulationBackend::Fastest)
        ImGui::TextDisabled("fastest: CPU or compute, as measured on this renderer");
}

}  // namespace prism::viewer
