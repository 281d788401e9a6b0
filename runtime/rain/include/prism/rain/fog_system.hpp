// GL drawing of the fog billboards (prism/rain/fog_billboards.hpp): one small vertex
// buffer of billboard centres, the animated noise texture array and the
// fog_billboards program (geometry shader). Created by RainScene only when the scene's
// fog has billboards (strength > 0).
//
// Usage (snippet: examples/snippets/rain_fog_system.cpp):
//
//     #include "prism/rain/fog_system.hpp"
//     prism::rain::FogSystem fog(programs, sceneFog, camera.eye);
//     fog.update(dt, camera.eye, wind);
//     fog.draw(camera, aspect, &sceneFog.distance, time);
#pragma once

#include <glm/vec3.hpp>

#include "prism/gl/handles.hpp"
#include "prism/view/camera.hpp"
#include "prism/rain/rain_programs.hpp"
#include "prism/rain/fog_billboards.hpp"

namespace prism::rain {

class FogSystem {
  public:
    FogSystem(RainPrograms& programs, const SceneFog& fog, const glm::vec3& eye);
    FogSystem(const FogSystem&) = delete;
    FogSystem& operator=(const FogSystem&) = delete;

    void update(float dt, const glm::vec3& eye, const glm::vec3& wind);
    // Premultiplied blending, depth test on, depth writes off; `distanceFog` non-null
    // selects the FOG=1 variant.
    void draw(const view::Camera& camera, float aspect, const view::Fog* distanceFog, float timeSeconds);
    void setStrength(float strength);  // [0, 1]
    float strength() const { return params_.strength; }
    const FogBillboardSimulation& simulation() const { return simulation_; }

  private:
    RainPrograms& programs_;
    FogBillboardParams params_;
    FogBillboardSimulation simulation_;
    FogNoiseArray noise_;
    gl::Buffer buffer_;
    gl::VertexArray vao_;
    gl::Texture noiseTexture_;
};

}  // namespace prism::rain
