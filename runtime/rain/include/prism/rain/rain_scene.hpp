// A rain scene: ground (a plane or gentle terrain), a sky colour, a directional sun and
// a point lamp (with a visible bulb), and, only when asked for, rain and fog. Models
// only what the description contains:
//   - no `rain`: no RainSystem, so no particle buffer, no compute update, no rain
//     program and no streak texture;
//   - no `fog`: only FOG=0 variants are built and used, no fog billboards, no noise.
// programsInUse() and the GL counters (prism::gl::objectCounts(), computeDispatches()) show it
// (tests/rain).
//
// Usage (snippet: examples/snippets/rain_rain_scene.cpp):
//
//     #include "prism/rain/rain_scene.hpp"
//     prism::rain::RainSceneDesc desc = prism::rain::defaultRainScene();
//     desc.rain->wind.strength = 5.0f;
//     prism::rain::RainScene scene(desc);  // needs a current GL context (4.3 with rain)
//     scene.update(1.0f / 60.0f);          // rain and fog billboards
//     prism::image::Image8 image = scene.render(200, 200);
#pragma once

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "prism/view/camera.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/image/image.hpp"
#include "prism/rain/rain_programs.hpp"
#include "prism/rain/fog_billboards.hpp"
#include "prism/rain/fog_system.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_system.hpp"

namespace prism::rain {

struct GroundDesc {
    float size = 240.0f;       // m, square centred on the origin
    int cells = 120;           // per side
    float hillHeight = 2.5f;   // m of the terrain's swell away from the flat centre (0 = plane)
    float flatRadius = 20.0f;  // m of flat ground around the origin
    glm::vec3 color{0.42f, 0.42f, 0.44f};
    float shininess = 48.0f;  // of the wet highlight
    float specular = 0.6f;
};

struct RainSceneDesc {
    view::Camera camera;
    glm::vec3 skyColor{0.33f, 0.36f, 0.42f};  // an overcast dusk: lit drops show
    RainLights lights;
    GroundDesc ground;
    bool showLampBulb = true;
    std::optional<RainParams> rain;  // no value: no rain is modelled at all
    std::optional<SceneFog> fog;     // no value: no fog code runs
    StreakTechnique technique = StreakTechnique::GeometryShader;
};

// A street-lamp scene with moderate rain from a fixed seed, camera at eye height
// looking along the street past the lamp; no fog.
RainSceneDesc defaultRainScene();
// The views the example and the golden images use: 0 looks past the lamp (lit from the
// side and behind), 1 looks back up the road towards the sun's side, 2 stands close to
// the lamp and looks up past it into the rain.
view::Camera rainSceneView(int view);

class RainScene {
  public:
    explicit RainScene(const RainSceneDesc& desc);
    ~RainScene();
    RainScene(const RainScene&) = delete;
    RainScene& operator=(const RainScene&) = delete;

    // Advances rain and fog billboards by dt seconds around the current camera.
    void update(float dt);
    void setCamera(const view::Camera& camera);
    const view::Camera& camera() const { return desc_.camera; }
    // Draws everything into the bound framebuffer of width x height pixels.
    void draw(int width, int height);
    // Renders into an own RGBA8 framebuffer and reads it back.
    image::Image8 render(int width, int height);

    RainSystem* rain() { return rain_.get(); }
    FogSystem* fogBillboards() { return fog_.get(); }
    const RainSceneDesc& desc() const { return desc_; }
    void setTechnique(StreakTechnique t) { desc_.technique = t; }

    RainPrograms& programs() { return *programs_; }
    // "shader (variant)" of every program drawn or dispatched so far, sorted.
    std::vector<std::string> programsInUse() const;
    float time() const { return time_; }

  private:
    RainSceneDesc desc_;
    std::unique_ptr<RainPrograms> programs_;
    std::unique_ptr<render::GpuMesh> ground_;
    std::unique_ptr<render::GpuMesh> bulb_;
    std::unique_ptr<render::GpuMesh> post_;
    std::unique_ptr<RainSystem> rain_;
    std::unique_ptr<FogSystem> fog_;
    float time_ = 0.0f;
};

// The ground mesh of `ground`: a grid whose heights swell smoothly outside flatRadius.
geometry::Mesh makeRainGround(const GroundDesc& ground);

}  // namespace prism::rain
