// Render-on-change scene display (scene_display.hpp).
#include "scene_display.hpp"

#include <set>

#include "prism/gl/gl.hpp"

namespace prism::viewer {

bool SceneDisplay::draw(SceneView& view, int left, int width, int height) {
    bool rendered = false;
    if (view.waterRunning && view.scene.water) {
        view.scene.water->seconds += view.waterStepSeconds;
        view.dirty = true;
    }
    if (view.dirty || width != width_ || height != height_) {
        view.scene.width = width;
        view.scene.height = height;
        blit_.upload(renderer_.render(view.scene));
        width_ = width;
        height_ = height;
        view.dirty = false;
        rendered = true;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    blit_.draw(left, width, height);
    return rendered;
}

std::string SceneDisplay::programLabel() const {
    std::set<std::string> seen;
    std::string label;
    for (const auto& v : renderer_.lastFrame().variants)
        if (seen.insert(v).second) label += (label.empty() ? "" : " + ") + v;
    return label.empty() ? "(no raster draw)" : label;
}

}  // namespace prism::viewer
