// Diffraction panel (open scene with a "diffraction" object): per object its height field,
// evaluation path, wavelength step, table size and number of Taylor terms N (or the
// tolerance that picks N); Stam diffraction thesis §3.
#include <imgui.h>

#include <string>

#include "panels.hpp"

namespace prism::viewer {

namespace {
bool hasDiffraction(const scene::Scene& scene) {
    for (const auto& object : scene.objects)
        if (object.diffraction) return true;
    return false;
}
}  // namespace

void drawDiffractionPanel(ViewerState& state) {
    if (!panelHeader("Diffraction", state, state.scene.open && hasDiffraction(state.scene.scene))) return;
    bool any = false;
    if (state.scene.open)
        for (std::size_t i = 0; i < state.scene.scene.objects.size(); ++i) {
            auto& object = state.scene.scene.objects[i];
            if (!object.diffraction) continue;
            any = true;
            auto& d = *object.diffraction;
            ImGui::PushID(static_cast<int>(i));
            ImGui::Text("object %zu: %s height field", i, d.heightFieldType.c_str());
            bool changed = false;
            const char paths[] = {'a', 'b', 'c'};
            for (char p : paths) {
                const std::string label = std::string("path ") + p;
                if (ImGui::RadioButton(label.c_str(), d.path == p)) d.path = p, changed = true;
                if (p != 'c') ImGui::SameLine();
            }
            const std::string step = std::to_string(d.wavelengthStepNm) + " nm";
            if (ImGui::BeginCombo("wavelength step", step.c_str())) {
                for (int s : {1, 2, 5, 10, 20})  // the steps the colour tables support (colour.hpp)
                    if (ImGui::Selectable((std::to_string(s) + " nm").c_str(), s == d.wavelengthStepNm)) {
                        d.wavelengthStepNm = s;
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            const std::string table = std::to_string(d.tableSize) + "^2";
            if (ImGui::BeginCombo("tables", table.c_str())) {
                for (int s : {128, 256, 512, 1024})
                    if (ImGui::Selectable((std::to_string(s) + "^2").c_str(), s == d.tableSize)) {
                        d.tableSize = s;
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            bool fixedTerms = d.terms.has_value();
            if (ImGui::Checkbox("fixed N", &fixedTerms)) {
                d.terms = fixedTerms ? std::optional<int>(8) : std::nullopt;
                changed = true;
            }
            if (d.terms) {
                changed |= ImGui::SliderInt("N (terms)", &*d.terms, 1, 40);
            } else {
                float tolerance = static_cast<float>(d.tolerance);
                if (ImGui::SliderFloat("tolerance", &tolerance, 1e-5f, 1e-1f, "%.0e", ImGuiSliderFlags_Logarithmic)) {
                    d.tolerance = tolerance;
                    changed = true;
                }
            }
            if (changed) state.scene.dirty = true;
            ImGui::PopID();
        }
    if (!any) ImGui::TextDisabled("open a diffraction scene (diffraction_*.json)");
}

}  // namespace prism::viewer
