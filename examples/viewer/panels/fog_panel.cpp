// Fog panel: distance fog density (catalogue view and scene) and, in a scene, the
// volumetric fog billboards' opacity.
#include <imgui.h>

#include <string>

#include "../viewer_actions.hpp"
#include "panels.hpp"

namespace prism::viewer {

void drawFogPanel(ViewerState& state) {
    if (!panelHeader("Fog", state, state.scene.open && (state.scene.scene.fog || state.scene.scene.fogBillboards)))
        return;
    const auto& fog = state.scene.open ? state.scene.scene.fog : state.catalogue.fog;
    float density = fog ? fog->density : 0.0f;
    if (ImGui::SliderFloat("density", &density, 0.0f, 1.0f, "%.3f"))
        setParameter(state, "fog.density", std::to_string(density));
    if (!state.scene.open) return;
    float billboards = state.scene.scene.fogBillboards.value_or(0.0f);
    if (ImGui::SliderFloat("billboards", &billboards, 0.0f, 1.0f, "%.2f"))
        setParameter(state, "fog.billboards", std::to_string(billboards));
}

}  // namespace prism::viewer
