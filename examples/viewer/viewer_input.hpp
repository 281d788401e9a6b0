// Input into the viewer: the keyboard (Left/Right/Up/Down rotate, S next shader, M next mesh,
// +/- subdivision, Esc quits) and --script events (viewer_script.hpp), both applied through
// viewer_actions.hpp so a scripted event takes exactly the path a key press takes.
//
//     installKeyHandler(window, state, catalog);     // before ImGuiLayer, which chains to it
//     std::string expected = applyEvent(state, catalog, window, script, event);  // `expect` text
#pragma once

#include <string>

#include "prism/catalog/shader_catalog.hpp"
#include "viewer_script.hpp"
#include "viewer_state.hpp"

struct GLFWwindow;

namespace prism::viewer {

void installKeyHandler(GLFWwindow* window, ViewerState& state, const catalog::Catalog& catalog);

// Applies one script event (throws std::invalid_argument with the reason when it cannot);
// returns the text of an `expect` event, to be checked after the frame, else empty.
std::string applyEvent(ViewerState& state, const catalog::Catalog& catalog, GLFWwindow* window,
                       const ViewerScript& script, const ScriptEvent& e);

}  // namespace prism::viewer
