// Rain panel (open scene): on or off, intensity class (RainCL Table 2), wind, level-of-detail
// rings and their density falloff, and the streak technique (geometry shader, instanced, points).
#include <imgui.h>

#include <string>

#include "prism/rain/rain_classes.hpp"
#include "prism/rain/rain_params.hpp"
#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

void drawRainPanel(ViewerState& state) {
    if (!panelHeader("Rain", state, state.scene.open && state.scene.scene.rain.has_value())) return;
    if (!state.scene.open) {
        ImGui::TextDisabled("open a scene (rain.json) to add rain");
        return;
    }
    auto& s = state.scene.scene;
    bool on = s.rain.has_value();
    if (ImGui::Checkbox("rain", &on)) setParameter(state, "rain.enabled", on ? "1" : "0");
    if (!s.rain) return;
    const std::string intensity(rain::rainClassInfo(s.rain->intensityClass).name);
    if (ImGui::BeginCombo("intensity", intensity.c_str())) {
        for (const auto& row : rain::rainClasses()) {
            const std::string name(row.name);
            if (ImGui::Selectable(name.c_str(), row.id == s.rain->intensityClass))
                setParameter(state, "rain.intensity", name);
        }
        ImGui::EndCombo();
    }
    if (s.rain->rateMillimetresPerHour) ImGui::Text("rate %.1f mm/h (from the scene)", *s.rain->rateMillimetresPerHour);
    bool changed = ImGui::SliderFloat("wind x (m/s)", &s.rain->wind.x, -15.0f, 15.0f);
    changed |= ImGui::SliderFloat("wind z (m/s)", &s.rain->wind.z, -15.0f, 15.0f);
    changed |= ImGui::SliderInt("LOD rings", &s.rain->lodRings, 1, 16);
    changed |= ImGui::SliderFloat("ring falloff", &s.rain->lodFalloff, 0.05f, 1.0f);
    if (changed) state.scene.dirty = true;
    const std::string technique(rain::techniqueName(s.rain->technique));
    if (ImGui::BeginCombo("technique", technique.c_str())) {
        using enum rain::StreakTechnique;
        for (rain::StreakTechnique t : {GeometryShader, Instanced, PointSprites}) {
            const std::string name(rain::techniqueName(t));
            if (ImGui::Selectable(name.c_str(), s.rain->technique == t)) setParameter(state, "rain.technique", name);
        }
        ImGui::EndCombo();
    }
}

}  // namespace prism::viewer
