// A scene as a JSON file describes it (docs/scenes.md): camera, lights, fog, objects
// (mesh, transform, material with its shader) and the optional rain and water
// settings. Plain data; prism/scene_loader.hpp reads it, prism/scene_renderer.hpp
// draws it with only the shader variants it needs.
//
// Usage (snippet: examples/snippets/scene_scene.cpp):
//
//     #include "prism/scene/scene.hpp"
//     prism::scene::Scene scene;  // built in code instead of read from JSON
//     scene.width = scene.height = 128;
//     scene.lights.directional.push_back({.direction = {-0.5f, -0.6f, -0.65f}, .color = {1, 1, 1}});
//     scene.fog = prism::view::Fog{.color = {0.6f, 0.65f, 0.7f}, .density = 0.1f};
//     prism::scene::SceneObject ball;
//     ball.mesh = "icosphere";
//     ball.shader = "phong";
//     ball.variantOverrides = {{"BLINN", "1"}};
//     scene.objects.push_back(ball);
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "prism/diffraction/material.hpp"
#include "prism/bluenoise/samplers.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/view/camera.hpp"
#include "prism/view/lighting.hpp"
#include "prism/water/water_simulation.hpp"

namespace prism::scene {

struct SceneObject {
    std::string mesh = "sphere";  // built-in name or a path to an .obj file
    unsigned subdivision = 3;
    glm::mat4 world{1.0f};
    std::string shader = "phong";
    std::vector<std::pair<std::string, std::string>> variantOverrides;  // e.g. BLINN=1
    view::Material material;
    // "shader": "diffraction" only: the material's "diffraction" parameters (height field,
    // path, wavelength step, tolerance or terms; prism/diffraction/material.hpp) and their
    // JSON pointer, which errors found when the tables are built name.
    std::optional<diffraction::DiffractionMaterial> diffraction;
    std::string diffractionPointer;
};

// Rain as a scene asks for it: an intensity class (the seed's Table 2) or a rate.
struct RainSettings {
    rain::RainClass intensityClass = rain::RainClass::Moderate;  // "intensity": drizzle .. cloudburst
    std::optional<double> rateMillimetresPerHour;                // overrides the class when given
    glm::vec3 wind{0.0f};
    unsigned seed = 1;
    float cylinderRadius = 20.0f;
    float cylinderHeight = 20.0f;
    std::optional<unsigned> particleBudget;
    // Set in code (the viewer's rain panel), not read from JSON: the level-of-detail rings
    // and their density falloff, and the streak technique (prism/rain/rain_params.hpp).
    int lodRings = 4;
    float lodFalloff = 0.5f;
    rain::StreakTechnique technique = rain::StreakTechnique::GeometryShader;
};

// Water as a scene asks for it (docs/water.md): a procedural terrain of gridSize^2
// cells, the rain rate (the scene's rain, else rainRateMillimetresPerHour), how long it
// has rained before the frame, and how fast loose soil soaks water up.
struct WaterSettings {
    unsigned gridSize = 128;
    float cellSize = 0.25f;                    // metres per cell
    double rainRateMillimetresPerHour = 10.0;  // used when the scene has no rain
    double seconds = 60.0;                     // simulated rain before the frame
    double soilMillimetresPerHour = 12.0;      // infiltration of loose soil (clay: 0.5)
    unsigned seed = 1;                         // of the procedural terrain
    float relief = 3.0f;                       // m between the lowest and highest hills
    float cloudCover = 0.6f;                   // of the procedural sky: 0 clear (bright) .. 1 overcast
    // Set in code (the viewer's water panel), not read from JSON: the water step, Fastest
    // (measured once per renderer, prism/water/backend_choice.hpp), Cpu or Gpu.
    water::SimulationBackend backend = water::SimulationBackend::Fastest;
};

// A Monte Carlo effect as a scene asks for it (docs/scenes.md, docs/bluenoise.md): soft
// shadows of spheres on a ground plane under a rectangular area light, seen from above,
// estimated on the CPU with `spp` samples per pixel from one of the three samplers.
// Frame `frame` alone, or (frames > 1) the mean of frames 0 .. frames-1.
struct StochasticSettings {
    bluenoise::SoftShadowScene light = bluenoise::SoftShadowScene::classic();  // light + spheres
    bluenoise::SamplerKind sampler = bluenoise::SamplerKind::BlueNoise;        // White, BlueNoise or Sorted
    int spp = 1;
    int frame = 0;
    int frames = 1;
    int maskSize = 64;  // void-and-cluster mask, maskSize^2
    unsigned maskSeed = 0;
    int block = 8;           // sorting block size of the sorted sampler
    int retargetEpochs = 8;  // annealing epochs of the sorted sampler's retarget permutation
};

struct Scene {
    std::string file;  // where it was read from, for messages
    view::Camera camera;
    int width = 512;
    int height = 512;
    glm::vec4 background{0.05f, 0.06f, 0.08f, 1.0f};
    view::Lights lights;
    std::optional<view::Fog> fog;
    // Volumetric fog billboards (rain system, soft against the ground): their peak opacity
    // in (0, 1] and the ground height they fade into; nullopt: distance fog only.
    std::optional<float> fogBillboards;
    float fogGroundHeight = 0.0f;
    std::vector<SceneObject> objects;
    std::optional<RainSettings> rain;
    std::optional<WaterSettings> water;
    std::optional<StochasticSettings> stochastic;  // replaces the raster image when given
};

}  // namespace prism::scene
