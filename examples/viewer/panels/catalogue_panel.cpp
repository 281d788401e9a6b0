// Catalogue panel: shader, variant axes (checkboxes for 0/1 axes, combos otherwise; values
// with no generated variant are greyed out), mesh and subdivision.
#include <imgui.h>

#include <iterator>
#include <string>

#include "../variant_choice.hpp"
#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

namespace {
std::string valueOf(const render::VariantValues& values, std::string_view axis) {
    for (const auto& [n, v] : values)
        if (n == axis) return v;
    return {};
}
bool isBoolean(const catalog::VariantAxis& axis) {
    return axis.values.size() == 2 && axis.values[0] == "0" && axis.values[1] == "1";
}
}  // namespace

void drawCataloguePanel(ViewerState& state, const catalog::Catalog& catalog, std::size_t programsCached) {
    if (!panelHeader("Catalogue", state, !state.scene.open)) return;
    auto& c = state.catalogue;
    if (state.scene.open) ImGui::TextDisabled("(close the scene to see the catalogue view)");
    if (ImGui::BeginCombo("shader", c.shader.c_str())) {
        for (const auto& s : catalog.shaders) {
            const std::string name(s.name);
            if (ImGui::Selectable(name.c_str(), name == c.shader)) selectShader(state, catalog, name);
        }
        ImGui::EndCombo();
    }
    const catalog::Shader* shader = catalog::findShader(catalog, c.shader);
    if (!shader) return;
    const auto current = effectiveVariant(*shader, render::featuresOf(c.lights, c.fog.has_value()), c.picks);
    for (const auto& axis : shader->axes) {
        const std::string name(axis.name), value = valueOf(current, axis.name);
        if (isBoolean(axis)) {
            bool on = value == "1";
            const bool canToggle = isValidChoice(*shader, current, axis.name, on ? "0" : "1");
            ImGui::BeginDisabled(!canToggle);
            if (ImGui::Checkbox(name.c_str(), &on)) pickAxis(state, name, on ? "1" : "0");
            ImGui::EndDisabled();
        } else if (ImGui::BeginCombo(name.c_str(), value.c_str())) {
            for (const auto& v : axis.values) {
                const std::string option(v);
                const bool valid = isValidChoice(*shader, current, axis.name, v);
                if (ImGui::Selectable(option.c_str(), option == value, valid ? 0 : ImGuiSelectableFlags_Disabled))
                    pickAxis(state, name, option);
            }
            ImGui::EndCombo();
        }
    }
    if (!c.picks.empty() && ImGui::Button("derive axes from lights and fog")) c.picks.clear();
    if (ImGui::BeginCombo("mesh", c.mesh.c_str())) {
        for (const char* m : kMeshes)
            if (ImGui::Selectable(m, c.mesh == m)) setParameter(state, "mesh", m);
        ImGui::EndCombo();
    }
    int subdivision = static_cast<int>(c.subdivision);
    if (ImGui::SliderInt("subdivision", &subdivision, 0, 6))
        setParameter(state, "subdivision", std::to_string(subdivision));
    ImGui::Text("programs cached: %zu", programsCached);
}

}  // namespace prism::viewer
