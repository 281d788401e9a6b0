// The rain particle and its simulation on the CPU: the reference that the GPU compute
// shaders (shader_sources/rain/rain_init.comp, rain_update.comp, both built on
// modules/rain/particles.glsl) are tested against. Same layout, same random numbers
// (prism/rain/random.hpp), same arithmetic in float, in the same order.
//
// Usage (snippet: examples/snippets/rain_rain_simulation.cpp):
//
//     #include "prism/rain/rain_simulation.hpp"
//     prism::rain::CpuRainSimulation sim(params, eye);  // seeds particleCountFor(params)
//     sim.step(1.0f / 60.0f, eye);                      // fall, wind, wrap around the camera
//     for (const auto& p : sim.particles()) use(p.position);
//
// Model (docs/rain.md): a drop falls at its terminal speed (constant per drop: the
// intensity's speed x a factor in [0.9, 1.1]) plus the wind plus a small constant
// sideways jitter. Out of the bottom of the cylinder it respawns at the top in its home
// column (`seed.xz`) (relative to the current camera); out of the side it is folded to the
// opposite side (antipodal); more than 3 radii away (a teleport) it returns to its
// home column. So every particle stays inside the cylinder after any camera move, and a
// fast move neither leaves gaps nor makes all drops respawn at once.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "prism/rain/rain_params.hpp"

namespace prism::rain {

// std430 layout of `RainParticle` in modules/rain/particles.glsl: 48 bytes.
struct Particle {
    glm::vec4 seed;      // xyz: offset from the cylinder centre (LOD rings); w: oscillation random [0, 1)
    glm::vec4 position;  // xyz: world position (m); w: brightness random [0, 1)
    glm::vec4 velocity;  // xyz: fall + jitter without wind (m/s); w: the drop's fall-speed factor
};
static_assert(sizeof(Particle) == 48, "Particle must match the std430 layout of RainParticle");

// Random channels of seedParticle (RAIN_CH_* in particles.glsl).
enum RandomChannel : std::uint32_t {
    kChannelRing = 0,
    kChannelRadius = 1,
    kChannelAngle = 2,
    kChannelHeight = 3,
    kChannelSpeed = 4,
    kChannelJitterX = 5,
    kChannelJitterZ = 6,
    kChannelOscillation = 7,
    kChannelBrightness = 8,
    kChannelWindDirection = 9,
};

// A step longer than this is clamped: a paused or very slow frame must not teleport
// the rain (a drop falls at most ~8 m per step, well inside the 20 m cylinder).
inline constexpr float kMaxStepSeconds = 1.0f;
// dt clamped to [0, kMaxStepSeconds]; throws RainParameterError for negative or NaN.
float clampStep(float dt);

// The per-step inputs shared by the CPU and GPU updates.
struct StepInputs {
    glm::vec3 center{0.0f};    // cylinder centre (cylinderCenter(params, eye))
    glm::vec2 cylinder{1.0f};  // radius, height
    glm::vec3 wind{0.0f};
    float fallSpeed = 0.0f;    // the intensity's fall speed (respawned drops use it)
    float shearHeight = 0.0f;  // height above the centre where the wind shear is zero (the eye's)
    float dt = 0.0f;           // already clamped
};

glm::vec2 foldIntoCylinder(glm::vec2 xz, glm::vec2 seedXZ, float radius);
Particle seedParticle(std::uint32_t index, std::uint32_t seed, const glm::vec3& center, const glm::vec2& cylinder,
                      const glm::vec2& lod, float fallSpeed, float jitter, const glm::vec3& wind, float shearHeight);
Particle stepParticle(Particle p, const StepInputs& in);

// Which level-of-detail ring a seed offset lies in (0 = innermost), for tests.
int lodRingOf(const Particle& p, float radius, int rings);

// The weather a simulation (CpuRainSimulation, RainSystem) runs under: its parameters, the
// intensity's rate and the wind's vector, kept in step by the one pair of setters of both.
struct RainWeather {
    explicit RainWeather(const RainParams& params);  // validates them (RainParameterError)
    // Validate, then set params.intensity and rate.
    void setIntensity(float intensity);
    // Validate, then set params.wind and wind.
    void setWind(const WindParams& wind);

    RainParams params;
    RainRate rate;
    glm::vec3 wind{0.0f};  // windVector(params)
};

class CpuRainSimulation {
  public:
    CpuRainSimulation(const RainParams& params, const glm::vec3& eye);

    // Advances by clampStep(dt) around the camera at `eye` (must be finite).
    void step(float dt, const glm::vec3& eye);
    // New intensity: the count follows particleCountFor(); new particles are seeded
    // around the last camera, removed ones are the last in the array.
    void setIntensity(float intensity);
    void setWind(const WindParams& wind);

    std::span<const Particle> particles() const { return {particles_.data(), count_}; }
    std::uint32_t particleCount() const { return count_; }
    const RainParams& params() const { return weather_.params; }
    glm::vec3 wind() const { return weather_.wind; }
    glm::vec3 center() const { return center_; }
    float fallSpeed() const { return weather_.rate.fallSpeed; }

  private:
    void resize(std::uint32_t count);

    RainWeather weather_;
    glm::vec3 center_{0.0f};
    float shearHeight_ = 0.0f;
    std::vector<Particle> particles_;
    std::uint32_t count_ = 0;
};

// Throws RainParameterError when `eye` is not finite.
void validateEye(const glm::vec3& eye);

}  // namespace prism::rain
