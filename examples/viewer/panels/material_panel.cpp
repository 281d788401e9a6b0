// Material and lights panel: colour, shininess, specular, ambient, and per directional
// light its colour and direction as two angles (azimuth, elevation of where it comes from);
// of the catalogue view, or of the open scene (its lights and first object).
#include <imgui.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

namespace {
// direction points from the light into the scene; the angles name where it comes from.
void anglesOf(const glm::vec3& direction, float& azimuth, float& elevation) {
    const glm::vec3 from = -glm::normalize(direction);
    azimuth = std::atan2(from.x, from.z);
    elevation = std::asin(glm::clamp(from.y, -1.0f, 1.0f));
}
glm::vec3 directionOf(float azimuth, float elevation) {
    return -glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                      std::cos(elevation) * std::cos(azimuth));
}
}  // namespace

void drawMaterialPanel(ViewerState& state) {
    if (!panelHeader("Material and lights", state, !state.scene.open)) return;
    // The catalogue view's, or in a scene its first object's material and the scene's lights.
    auto& objects = state.scene.scene.objects;
    view::Lights& lights = state.scene.open ? state.scene.scene.lights : state.catalogue.lights;
    view::Material* material = !state.scene.open ? &state.catalogue.material
                               : objects.empty() ? nullptr
                                                 : &objects.front().material;
    if (state.scene.open) ImGui::TextDisabled("the scene's lights and its first object");
    bool changed = false;
    if (material) {
        changed |= ImGui::ColorEdit3("colour", &material->color.r, ImGuiColorEditFlags_NoInputs);
        changed |=
            ImGui::SliderFloat("shininess", &material->shininess, 1.0f, 256.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
        changed |= ImGui::SliderFloat("specular", &material->specular, 0.0f, 1.0f);
    }
    changed |= ImGui::ColorEdit3("ambient", &lights.ambient.r, ImGuiColorEditFlags_NoInputs);
    int count = static_cast<int>(lights.directional.size());
    if (ImGui::SliderInt("lights", &count, 0, 4)) setParameter(state, "lights.directional", std::to_string(count));
    for (std::size_t i = 0; i < lights.directional.size(); ++i) {
        auto& light = lights.directional[i];
        ImGui::PushID(static_cast<int>(i));
        const std::string label = i == 0 ? "key light" : i == 1 ? "fill light" : "light " + std::to_string(i + 1);
        ImGui::TextUnformatted(label.c_str());
        float azimuth = 0, elevation = 0;
        anglesOf(light.direction, azimuth, elevation);
        bool moved = ImGui::SliderAngle("azimuth", &azimuth, -180.0f, 180.0f);
        moved |= ImGui::SliderAngle("elevation", &elevation, -89.0f, 89.0f);
        if (moved) light.direction = directionOf(azimuth, elevation);
        changed |= moved;
        changed |= ImGui::ColorEdit3("light colour", &light.color.r, ImGuiColorEditFlags_NoInputs);
        ImGui::PopID();
    }
    if (changed && state.scene.open) state.scene.dirty = true;
}

}  // namespace prism::viewer
