// A rain-and-water scene: a height-map terrain under a procedural cloudy skybox, with
// (optionally) a water map fed by rain, drawn with sky reflection, Fresnel transparency
// and capillary ripples. Only what the scene needs is created: a scene without water
// has no water map, no simulation and no water program; without rain there are no
// ripple textures and the water program is the RIPPLES=0 variant.
//
// Usage (snippet: examples/snippets/water_water_scene.cpp):
//
//     #include "prism/water/water_scene.hpp"
//     using namespace prism::water;
//     WaterSceneDescription d;
//     d.terrain = proceduralTerrain({.width = 256, .height = 256});  // default: 512 x 512
//     d.rainMmPerHour = rainRateMmPerHour(RainClass::Heavy);
//     d.fog = prism::view::Fog{};
//     WaterScene scene(std::move(d));
//     scene.advance(1.0);  // one second of rain
//     auto ctx = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
//     WaterSceneRenderer renderer(scene);
//     prism::image::Image8 img = renderer.renderImage(overviewCamera(scene.terrain()), 640, 480);
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "prism/view/camera.hpp"
#include "prism/image/image.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/view/lighting.hpp"
#include "prism/water/backend_choice.hpp"
#include "prism/water/height_field.hpp"
#include "prism/water/procedural_textures.hpp"
#include "prism/water/water_simulation.hpp"

namespace prism::water {

// How the water surface looks (RainCL §4.3; docs/water.md "Drawing").
struct WaterLook {
    float threshold = 1e-5f;              // m: a surface vertex with less water counts as dry
    float shoreFadeDepth = 0.004f;        // m: the surface fades in with depth from 0 to this
    float fresnelF0 = 0.02f;              // reflectance looking straight down (water)
    glm::vec3 tint{0.10f, 0.14f, 0.13f};  // body colour of deep water (rain water over soil)
    float absorption = 3.0f;              // 1/m: the refracted ground shows by exp(-absorption path)
    float rippleScale = 1.2f;             // ripple-map repeats per metre
    float wetDarkening = 0.6f;            // albedo factor of soaked ground
    float wetFilmDepth = 0.0008f;         // m: the terrain darkens by 1 - exp(-depth / this)
};

struct WaterSceneDescription {
    HeightField terrain;                                 // empty: proceduralTerrain() (the default 512x512 water map)
    std::vector<float> permeability;                     // m/s per cell; empty: proceduralPermeability(terrain)
    bool water = true;                                   // false: terrain and sky only
    double rainMmPerHour = 0.0;                          // constant rain rate (see rain_rates.hpp for classes)
    SimulationBackend backend = SimulationBackend::Cpu;  // Fastest: measured once (backend_choice.hpp)
    WaterParams params;
    view::Lights lights = defaultSun();
    std::optional<view::Fog> fog;
    SkyOptions sky;
    WaterLook look;

    // A low sun from the upper right with a bluish overcast ambient.
    static view::Lights defaultSun();
};

// The water map with its rain and ripple clock; exists only in scenes with water.
class WaterSystem {
  public:
    WaterSystem(const HeightField& terrain, std::vector<float> permeability, const WaterParams& params,
                SimulationBackend backend, double rainMmPerHour);

    void setRain(double mmPerHour);  // >= 0
    double rainMmPerHour() const { return rainMmPerHour_; }
    bool hasRain() const { return rainMmPerHour_ > 0.0; }

    SubstepPlan advance(double dt);
    // Position in the 16-frame ripple cycle, in [0, 16); advances at
    // rippleFramesPerSecond(rain), so it stands still without rain.
    double rippleFrame() const { return rippleFrame_; }

    WaterSimulation& simulation() { return *simulation_; }
    const WaterSimulation& simulation() const { return *simulation_; }

  private:
    std::unique_ptr<WaterSimulation> simulation_;
    double rainMmPerHour_ = 0.0;
    double rippleFrame_ = 0.0;
};

class WaterScene {
  public:
    explicit WaterScene(WaterSceneDescription description);

    const WaterSceneDescription& description() const { return description_; }
    const HeightField& terrain() const { return description_.terrain; }
    const std::vector<float>& permeability() const { return description_.permeability; }
    bool hasWater() const { return water_ != nullptr; }
    WaterSystem* water() { return water_.get(); }
    const WaterSystem* water() const { return water_.get(); }

    // view::Fog on or off; the renderer picks the FOG=1 or FOG=0 programs at the next draw.
    void setFog(std::optional<view::Fog> fog) { description_.fog = fog; }

    // Advances the water by dt seconds (nothing to do in a scene without water).
    void advance(double dt);
    // The model matrix that centres the terrain on the origin.
    glm::mat4 world() const;

  private:
    WaterSceneDescription description_;
    std::unique_ptr<WaterSystem> water_;
};

// Cameras that frame a terrain: from above a corner, and low over the ground looking
// across towards the centre.
view::Camera overviewCamera(const HeightField& terrain);
view::Camera groundCamera(const HeightField& terrain);

// GL objects a renderer created: the evidence for "only what the scene needs".
struct SceneRenderStats {
    std::size_t programs = 0;  // linked GL programs
    std::size_t textures = 0;
    std::size_t buffers = 0;
    std::size_t vertexArrays = 0;
    bool waterSurface = false;    // water program, mesh and depth textures exist
    bool rippleTextures = false;  // the 16-frame ripple array exists
};

// Draws a WaterScene. Needs a current GL context (3.3 is enough for the drawing; a GPU
// simulation needs 4.3). Terrain and sky resources are made at construction; the water
// surface's only when the scene has water; the ripple array when rain first falls.
class WaterSceneRenderer {
  public:
    explicit WaterSceneRenderer(const WaterScene& scene);
    ~WaterSceneRenderer();
    WaterSceneRenderer(const WaterSceneRenderer&) = delete;
    WaterSceneRenderer& operator=(const WaterSceneRenderer&) = delete;

    // Draws into the bound framebuffer, setting the viewport to width x height.
    void draw(const view::Camera& camera, int width, int height);
    // Draws into an off-screen RGBA8 target and reads it back (row 0 at the top).
    image::Image8 renderImage(const view::Camera& camera, int width, int height);

    SceneRenderStats stats() const;
    render::ProgramCache& programCache();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace prism::water
