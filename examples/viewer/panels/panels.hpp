// The viewer's Dear ImGui panels, one file each, all editing ViewerState through
// viewer_actions.hpp: catalogue, material and lights, scene, rain, water, fog,
// diffraction, blue noise, and the overlay (frame time, program in use, reference error).
//
//     drawControlPanels(state, catalog, sceneFiles, cache.size());  // between ImGui::NewFrame and Render
//     drawOverlay(state, cache.size());
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "../viewer_state.hpp"

namespace prism::viewer {

inline constexpr float kPanelWidth = 330.0f;  // the controls column on the left

void drawControlPanels(ViewerState& state, const catalog::Catalog& catalog, const std::vector<std::string>& sceneFiles,
                       std::size_t programsCached);
void drawCataloguePanel(ViewerState& state, const catalog::Catalog& catalog, std::size_t programsCached);
void drawMaterialPanel(ViewerState& state);
void drawScenePanel(ViewerState& state, const std::vector<std::string>& sceneFiles);
void drawRainPanel(ViewerState& state);
void drawWaterPanel(ViewerState& state);
void drawFogPanel(ViewerState& state);
void drawDiffractionPanel(ViewerState& state);
void drawBlueNoisePanel(ViewerState& state);
void drawOverlay(ViewerState& state, float viewLeft);

// A collapsing header for one panel. Each time the view changes (a scene opened or
// closed) the panels that apply to the new view open and the others close; in between the
// user's clicks decide.
bool panelHeader(const char* label, const ViewerState& state, bool appliesToView);

// The message of the last action a panel could not apply (shown in red), or empty.
std::string& panelError();

}  // namespace prism::viewer
