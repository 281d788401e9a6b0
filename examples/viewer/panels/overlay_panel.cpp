// The overlay at the top right of the view: frame time (GPU via GL_TIME_ELAPSED, or CPU),
// the program in use with its variant, and the error toggle and readout (exact sphere for
// the catalogue view, the high-sample reference for a sampling scene).
#include <imgui.h>

#include <algorithm>

#include "panels.hpp"

namespace prism::viewer {

void drawOverlay(ViewerState& state, float viewLeft) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 8.0f, 8.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(io.DisplaySize.x - viewLeft - 16.0f, 400.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("Overlay", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const auto& r = state.readouts;
    ImGui::Text("%.2f ms per frame (%s)", r.frameMs, r.gpuTimed ? "GPU, GL_TIME_ELAPSED" : "CPU clock");
    if (state.scene.open) ImGui::Text("last scene render: %.0f ms (on a parameter change)", r.sceneRenderMs);
    const float wrap = std::min(380.0f, io.DisplaySize.x - viewLeft - 32.0f);  // keep the view visible
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
    ImGui::TextWrapped("program: %s", r.program.c_str());
    const bool sampling = state.scene.open && state.scene.scene.stochastic.has_value();
    if (!state.scene.open || sampling) {
        ImGui::Checkbox(sampling ? "error vs 1024-sample reference" : "error vs exact sphere",
                        &state.readouts.referenceOn);
        if (state.readouts.referenceOn) ImGui::TextWrapped("%s", r.referenceText.c_str());
    }
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace prism::viewer
