// What keys, panels and --script events do to the viewer state, in one place, so a
// scripted event takes exactly the path a click or key press takes.
//
//     selectShader(state, catalog, "gouraud");
//     openScene(state, "examples/scenes/rain.json");
//     setParameter(state, "rain.intensity", "heavy");   // throws std::invalid_argument if unknown
#pragma once

#include <string>

#include "prism/catalog/shader_catalog.hpp"
#include "viewer_state.hpp"

namespace prism::viewer {

void selectShader(ViewerState& state, const catalog::Catalog& catalog, const std::string& shader);
void nextShader(ViewerState& state, const catalog::Catalog& catalog);  // key S
void nextMesh(ViewerState& state);                                     // key M
void pickAxis(ViewerState& state, const std::string& axis, const std::string& value);
void openScene(ViewerState& state, const std::string& path);  // throws on a bad file
void closeScene(ViewerState& state);                          // back to the catalogue view

// Named parameters, as --script's `set NAME VALUE` and the panels use them:
//   mesh NAME, subdivision N, lights.directional N, material.shininess X, material.specular X
//   (of the open scene's lights and first object when a scene is open),
//   fog.density X (0: no fog), reference 0|1,
//   rain.enabled 0|1, rain.intensity CLASS, rain.wind.x X, rain.wind.z X, rain.lodRings N,
//   rain.technique gs|instanced|points, water.running 0|1, water.seconds X,
//   water.backend fastest|cpu|gpu, fog.billboards X (0: none),
//   bluenoise.sampler white|bluenoise|sorted, bluenoise.spp N, bluenoise.frames N
void setParameter(ViewerState& state, const std::string& name, const std::string& value);

const char* const kMeshes[] = {"sphere", "icosphere", "torus", "cube", "trefoil"};

}  // namespace prism::viewer
