// Blue-noise panel (open scene with "stochastic" soft shadows): sampler, samples per pixel
// and accumulated frames (temporal blue noise thesis §4).
#include <imgui.h>

#include "panels.hpp"

namespace prism::viewer {

void drawBlueNoisePanel(ViewerState& state) {
    if (!panelHeader("Blue noise", state, state.scene.open && state.scene.scene.stochastic.has_value())) return;
    if (!state.scene.open || !state.scene.scene.stochastic) {
        ImGui::TextDisabled("open a sampling scene (soft_shadows.json)");
        return;
    }
    auto& st = *state.scene.scene.stochastic;
    int sampler = static_cast<int>(st.sampler);
    bool changed = ImGui::Combo("sampler", &sampler, "white\0blue noise\0sorted\0");
    if (changed) st.sampler = static_cast<bluenoise::SamplerKind>(sampler);
    changed |= ImGui::SliderInt("spp", &st.spp, 1, 64);
    changed |= ImGui::SliderInt("frames (accumulate)", &st.frames, 1, 32);
    changed |= ImGui::SliderInt("frame", &st.frame, 0, 63);
    if (changed) state.scene.dirty = true;
}

}  // namespace prism::viewer
