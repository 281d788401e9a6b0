// The controls column: one ImGui window at the left edge holding every panel.
#include <imgui.h>

#include <string>

#include "panels.hpp"

namespace prism::viewer {

std::string& panelError() {
    static std::string error;
    return error;
}

bool panelHeader(const char* label, const ViewerState& state, bool appliesToView) {
    if (state.panelsRelayout) ImGui::SetNextItemOpen(appliesToView, ImGuiCond_Always);
    return ImGui::CollapsingHeader(label);
}

void drawControlPanels(ViewerState& state, const catalog::Catalog& catalog, const std::vector<std::string>& sceneFiles,
                       std::size_t programsCached) {
    const std::string view = state.scene.open ? state.scene.file : "catalogue";
    state.panelsRelayout = view != state.panelsView;
    state.panelsView = view;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("Prism viewer", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-140.0f);
    drawScenePanel(state, sceneFiles);
    drawCataloguePanel(state, catalog, programsCached);
    drawMaterialPanel(state);
    drawFogPanel(state);
    drawRainPanel(state);
    drawWaterPanel(state);
    drawDiffractionPanel(state);
    drawBlueNoisePanel(state);
    ImGui::PopItemWidth();
    if (!panelError().empty()) ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "%s", panelError().c_str());
    ImGui::End();
}

}  // namespace prism::viewer
