// Everything the viewer's panels, script and keys edit, in one place: the catalogue view
// (shader, axis picks, mesh, material, lights, fog), the open scene and its systems, and
// the live readouts (program in use, frame time, reference error). Plain data.
#pragma once

#include <optional>
#include <string>

#include "prism/render/offscreen_render.hpp"
#include "prism/scene/scene.hpp"
#include "prism/view/lighting.hpp"

namespace prism::viewer {

struct CatalogueView {
    std::string shader = "phong";
    render::VariantValues picks;  // axis values chosen in the panel or by --variant
    std::string mesh = "sphere";
    unsigned subdivision = 3;
    view::Material material;
    view::Lights lights = render::defaultLights();  // a key and a fill light
    std::optional<view::Fog> fog;
    float yaw = 0.0f, pitch = 0.3f;
};

struct SceneView {
    bool open = false;
    std::string file;
    scene::Scene scene;
    bool dirty = true;  // parameters changed: render the scene again
    bool waterRunning = false;
    double waterStepSeconds = 5.0;  // simulated seconds added per frame while running
    double waterStartSeconds = 60.0;
};

struct Readouts {
    std::string program;  // "<shader> <variant>" of the catalogue view, or the scene's draws
    double frameMs = 0.0;
    bool gpuTimed = false;       // frameMs from GL_TIME_ELAPSED (else CPU wall time)
    bool referenceOn = false;    // the exact-sphere toggle
    std::string referenceText;   // "mean 1.23 max 17 (8-bit units)" or why there is none
    double sceneRenderMs = 0.0;  // the last full render of the open scene (CPU wall time)
};

struct ViewerState {
    CatalogueView catalogue;
    SceneView scene;
    Readouts readouts;
    bool meshDirty = true;
    bool panels = true;
    std::string panelsView;       // the view the panels were last opened for
    bool panelsRelayout = false;  // this frame: the view changed, open the panels that apply
};

}  // namespace prism::viewer
