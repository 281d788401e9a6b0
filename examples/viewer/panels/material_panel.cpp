// Material and lights panel: colour, shininess, specular, ambient, and per directional
// light its colour and direction as two angles (azimuth, elevation of where it comes from).
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
    auto& c = state.catalogue;
    ImGui::ColorEdit3("colour", &c.material.color.r, ImGuiColorEditFlags_NoInputs);
    ImGui::SliderFloat("shininess", &c.material.shininess, 1.0f, 256.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("specular", &c.material.specular, 0.0f, 1.0f);
    ImGui::ColorEdit3("ambient", &c.lights.ambient.r, ImGuiColorEditFlags_NoInputs);
    int count = static_cast<int>(c.lights.directional.size());
    if (ImGui::SliderInt("lights", &count, 0, 4)) setParameter(state, "lights.directional", std::to_string(count));
    for (std::size_t i = 0; i < c.lights.directional.size(); ++i) {
        auto& light = c.lights.directional[i];
        ImGui::PushID(static_cast<int>(i));
        const std::string label = i == 0 ? "key light" : i == 1 ? "fill light" : "light " + std::to_string(i + 1);
        ImGui::TextUnformatted(label.c_str());
        float azimuth = 0, elevation = 0;
        anglesOf(light.direction, azimuth, elevation);
        bool moved = ImGui::SliderAngle("azimuth", &azimuth, -180.0f, 180.0f);
        moved |= ImGui::SliderAngle("elevation", &elevation, -89.0f, 89.0f);
        if (moved) light.direction = directionOf(azimuth, elevation);
        ImGui::ColorEdit3("light colour", &light.color.r, ImGuiColorEditFlags_NoInputs);
        ImGui::PopID();
    }
}

}  // namespace prism::viewer
