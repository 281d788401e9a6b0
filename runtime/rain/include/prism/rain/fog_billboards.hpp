// Volumetric fog for the rain scene (RainCL §4.4): the distance fog of
// modules/fog.glsl (the FOG shader variant) plus a few large, slowly drifting,
// camera-facing billboards textured with animated noise, whose strength is adjustable.
// This header is the CPU part: parameters, the noise texture array and the billboard
// motion (GL drawing: prism/rain/fog_system.hpp).
//
// Usage (snippet: examples/snippets/rain_fog_billboards.cpp):
//
//     #include "prism/rain/fog_billboards.hpp"
//     prism::rain::SceneFog fog;       // distance fog + billboards
//     fog.billboards.strength = 0.5f;  // 0: distance fog only, no billboards
//     prism::rain::FogNoiseArray noise = prism::rain::generateFogNoise(64, 16, 7);
//     prism::rain::FogBillboardSimulation sim(fog.billboards, eye);
//     sim.step(dt, eye, wind);
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

#include "prism/view/lighting.hpp"

namespace prism::rain {

struct FogBillboardParams {
    float strength = 0.45f;   // peak opacity of a billboard, [0, 1]; 0 = no billboards at all
    int count = 40;           // 1..4096
    float size = 16.0f;       // m, edge of a billboard
    float radius = 40.0f;     // m, around the camera
    float minHeight = 0.5f;   // m, world y of the lowest centre
    float maxHeight = 4.0f;   // m
    float drift = 0.3f;       // m/s of each billboard's own slow motion
    float windFactor = 0.5f;  // share of the wind that carries the billboards
    glm::vec3 color{0.50f, 0.52f, 0.57f};
    std::uint32_t seed = 7;
    // Soft particles against the ground: a billboard fades to nothing within
    // softDistance above groundHeight (world y), so where it dips into the ground there
    // is no hard line (the depth test alone cuts it straight). softDistance > 0.
    float groundHeight = 0.0f;
    float softDistance = 1.5f;
};

struct SceneFog {
    view::Fog distance{glm::vec3(0.42f, 0.45f, 0.50f), 0.035f};  // modules/fog.glsl; the sky fogs fully
    FogBillboardParams billboards;
};

// Throws rain::RainParameterError naming the bad field.
void validate(const SceneFog& fog);

// The fog over ground at world height `groundHeight` (a scene's or a terrain's lowest
// point): the `distance` fog, and billboards of `strength` in its colour whose centres
// float 0.5 to 4 m above the ground and which fade out where they meet it.
SceneFog fogOverGround(const view::Fog& distance, float strength, float groundHeight);

// Animated, tileable noise: `layers` time slices of periodic 3D fBm value noise, so
// layer L-1 blends seamlessly into layer 0. R8, size x size x layers.
struct FogNoiseArray {
    int size = 0;
    int layers = 0;
    std::vector<std::uint8_t> texels;
};
FogNoiseArray generateFogNoise(int size = 64, int layers = 16, std::uint32_t seed = 7);

class FogBillboardSimulation {
  public:
    FogBillboardSimulation(const FogBillboardParams& params, const glm::vec3& eye);
    // Moves every billboard by (drift + windFactor * wind) * dt and folds the ones that
    // left the circle of `radius` around the camera to its other side.
    void step(float dt, const glm::vec3& eye, const glm::vec3& wind);
    // xyz: centre, w: a random in [0, 1) (noise offset and animation phase).
    const std::vector<glm::vec4>& billboards() const { return billboards_; }
    const FogBillboardParams& params() const { return params_; }

  private:
    FogBillboardParams params_;
    std::vector<glm::vec4> billboards_;
    std::vector<glm::vec3> drift_;
};

}  // namespace prism::rain
