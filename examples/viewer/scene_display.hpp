// The scene view: a scene (docs/scenes.md) drawn by prism::scene::SceneRenderer with
// everything it asks for (rain, water, fog billboards, diffraction, blue-noise
// sampling). A frame is rendered again only when a panel changed the scene or the window
// size changed; otherwise the last image is blitted.
//
//     SceneDisplay display(catalog);
//     display.draw(state.scene, 0, width, height);
//     display.programLabel(state.scene);  // "phong DIRECTIONAL_LIGHTS=1,... + rain gs-quads (41933 particles)"
#pragma once

#include <string>

#include "image_blit.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "viewer_state.hpp"

namespace prism::viewer {

class SceneDisplay {
  public:
    explicit SceneDisplay(const catalog::Catalog& catalog) : renderer_(catalog) {}
    // Renders when needed, then blits; returns true when a new frame was rendered.
    bool draw(SceneView& view, int left, int width, int height);
    double lastRenderMs() const { return lastRenderMs_; }
    // Why the last render failed (the previous frame stays on screen), or empty.
    const std::string& error() const { return error_; }
    std::string programLabel(const SceneView& view) const;
    const scene::SceneRenderer& renderer() const { return renderer_; }

  private:
    scene::SceneRenderer renderer_;
    ImageBlit blit_;
    int width_ = 0, height_ = 0;
    double lastRenderMs_ = 0.0;
    std::string error_;
};

}  // namespace prism::viewer
