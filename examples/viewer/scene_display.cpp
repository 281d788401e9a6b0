// Render-on-change scene display (scene_display.hpp).
#include "scene_display.hpp"

#include <chrono>
#include <exception>
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
        width_ = width;
        height_ = height;
        view.dirty = false;
        const auto start = std::chrono::steady_clock::now();
        try {
            blit_.upload(renderer_.render(view.scene));
            error_.clear();
            rendered = true;
        } catch (const std::exception& e) {  // settings the systems reject: keep the last frame
            error_ = e.what();
            view.waterRunning = false;
        }
        lastRenderMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    blit_.draw(left, width, height);
    return rendered;
}

std::string SceneDisplay::programLabel(const SceneView& view) const {
    std::set<std::string> seen;
    std::string label;
    for (const auto& v : renderer_.lastFrame().variants)
        if (seen.insert(v).second) label += (label.empty() ? "" : " + ") + v;
    if (const auto& st = view.scene.stochastic) {
        static const char* const kSamplers[] = {"white", "blue-noise", "sorted", "stack"};
        const auto kind = static_cast<std::size_t>(st->sampler);
        label += (label.empty() ? "" : " + ") + std::string("soft shadows on the CPU: ") +
                 (kind < 4 ? kSamplers[kind] : "?") + " sampler, " + std::to_string(st->spp) + " spp x " +
                 std::to_string(st->frames) + " frames";
    }
    return label.empty() ? "(no draw)" : label;
}

}  // namespace prism::viewer
