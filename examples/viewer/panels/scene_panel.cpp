// Scene panel: the catalogue view or one of the example scenes (examples/scenes/*.json).
#include <imgui.h>

#include <exception>
#include <filesystem>

#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

void drawScenePanel(ViewerState& state, const std::vector<std::string>& sceneFiles) {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::string current =
        state.scene.open ? std::filesystem::path(state.scene.file).filename().string() : "catalogue view";
    if (ImGui::BeginCombo("scene", current.c_str())) {
        if (ImGui::Selectable("catalogue view", !state.scene.open)) closeScene(state);
        for (const auto& file : sceneFiles) {
            const std::string name = std::filesystem::path(file).filename().string();
            if (ImGui::Selectable(name.c_str(), state.scene.open && state.scene.file == file)) {
                try {
                    openScene(state, file);
                    panelError().clear();
                } catch (const std::exception& e) {
                    panelError() = e.what();
                }
            }
        }
        ImGui::EndCombo();
    }
    if (state.scene.open)
        ImGui::Text("%zu objects, %zu + %zu lights", state.scene.scene.objects.size(),
                    state.scene.scene.lights.directional.size(), state.scene.scene.lights.points.size());
}

}  // namespace prism::viewer
