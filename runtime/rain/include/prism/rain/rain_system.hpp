// The GPU rain: particles in one GL buffer, seeded and stepped by compute shaders
// (rain_init.comp, rain_update.comp), drawn as light-dependent streaks with one of
// three techniques. Create one only when a scene has rain (see prism/rain/rain_scene.hpp):
// nothing is allocated or built before the first particle needs it.
//
// Usage (snippet: examples/snippets/rain_rain_system.cpp):
//
//     #include "prism/rain/rain_programs.hpp"
//     #include "prism/rain/rain_system.hpp"
//     prism::rain::RainPrograms programs;
//     prism::rain::RainSystem rain(programs, params, camera.eye);
//     rain.update(1.0f / 60.0f, camera.eye);  // compute dispatch
//     rain.draw({.camera = camera, .aspect = 1.f, .viewportHeight = 800, .lights = lights});
//     std::vector<prism::rain::Particle> ps = rain.readParticles();  // tests
//
// Needs a current GL >= 4.3 context (compute shaders) for its whole life; throws
// gl::ComputeUnavailableError otherwise. Memory: 48 bytes per particle in the simulation buffer, as
// many again for the culled copy the techniques draw from (made at the first culled draw), plus the
// 450-layer streak texture array (1.8 MB, RGBA8).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "prism/gl/compute.hpp"
#include "prism/gl/handles.hpp"
#include "prism/view/camera.hpp"
#include "prism/rain/rain_programs.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_simulation.hpp"
#include "prism/view/lighting.hpp"

namespace prism::rain {

// StreakTechnique, techniqueName and parseTechnique: prism/rain/rain_params.hpp.
std::string_view techniqueShader(StreakTechnique t);  // rain_streaks, rain_instanced, rain_points

// The rain scene's lights: ambient, a directional sun and a lamp with falloff
// (modules/rain/drop_lights.glsl).
struct RainLights {
    glm::vec3 ambient{0.13f, 0.14f, 0.16f};
    view::DirectionalLight sun{glm::vec3(-0.3f, -0.8f, -0.5f), glm::vec3(0.42f, 0.42f, 0.48f)};
    view::PointLight lamp{glm::vec3(2.0f, 3.2f, -6.0f), glm::vec3(8.0f, 6.2f, 3.8f)};
    float lampRange = 1.5f;  // m: the lamp's light halves at this distance
};

struct RainDrawInputs {
    view::Camera camera;
    float aspect = 1.0f;
    int viewportHeight = 512;  // pixels (minimum streak width)
    RainLights lights;
    const view::Fog* fog = nullptr;  // non-null: the FOG=1 variant
    StreakTechnique technique = StreakTechnique::GeometryShader;
    // true: a compute pass (rain_cull.comp) first keeps only the particles whose streak can reach a pixel
    // of this view, in their order, and the technique draws those (indirect); false: every particle
    // goes through the vertex stages. The image is the same either way.
    bool cullToView = true;
};

class RainSystem {
  public:
    static constexpr std::size_t kBytesPerParticle = sizeof(Particle);

    RainSystem(RainPrograms& programs, const RainParams& params, const glm::vec3& eye);
    RainSystem(const RainSystem&) = delete;
    RainSystem& operator=(const RainSystem&) = delete;

    // One step of clampStep(dt) around the camera at `eye` (finite).
    void update(float dt, const glm::vec3& eye);
    // Draws into the bound framebuffer with blending, depth test on, depth writes off.
    void draw(const RainDrawInputs& in);

    // The count follows particleCountFor(); more particles are seeded around the last
    // camera (the buffer grows, keeping the old ones), fewer just stop being drawn.
    void setIntensity(float intensity);
    void setWind(const WindParams& wind);

    std::uint32_t particleCount() const { return count_; }
    std::uint32_t capacity() const { return capacity_; }
    const RainParams& params() const { return weather_.params; }
    glm::vec3 wind() const { return weather_.wind; }
    glm::vec3 center() const { return center_; }
    float fallSpeed() const { return weather_.rate.fallSpeed; }
    std::uint64_t steps() const { return steps_; }
    // Bytes of GPU memory: particle buffer + culled copy + draw commands + streak texture (0 before the
    // first particle); particleBytes() without the texture.
    std::size_t gpuBytes() const;
    std::size_t particleBytes() const;
    unsigned particleBuffer() const { return particles_.id(); }
    // Particles the last culled draw kept (read back from its draw commands; tests, benchmarks);
    // particleCount() before any culled draw.
    std::uint32_t visibleCount() const;

    // The first particleCount() particles, read back from the GPU.
    std::vector<Particle> readParticles() const;

  private:
    void resize(std::uint32_t count);
    void seedRange(std::uint32_t first, std::uint32_t end);
    void ensureStreakTexture();
    void bindAttributes(const gl::VertexArray& vao, const gl::Buffer& source, unsigned divisor);
    std::uint32_t cullBlocks() const;
    void setStreakUniforms(gl::Program& p, const RainDrawInputs& in) const;
    void cullToView(const RainDrawInputs& in);
    void drawAll(StreakTechnique technique) const;
    void drawVisible(StreakTechnique technique) const;

    RainPrograms& programs_;
    RainWeather weather_;
    float fastestFall_ = 0.0f;  // m/s: the fastest fall speed any drop may still have (culling bound)
    glm::vec3 center_{0.0f};
    float shearHeight_ = 0.0f;
    std::uint32_t count_ = 0;
    std::uint32_t capacity_ = 0;
    std::uint64_t steps_ = 0;
    gl::Buffer particles_;
    gl::VertexArray pointsVao_;                 // GS and point sprites: one vertex per particle
    gl::VertexArray instancedVao_;              // instanced quads: divisor 1
    bool vaoReadsVisible_[2] = {false, false};  // [instanced]: the VAO reads visible_, not particles_
    gl::Buffer visible_;       // rain_cull.comp's output: the particles this view needs, per block in order
    gl::Buffer drawCommands_;  // its indirect commands: points (GS, sprites) per block, then instanced
    gl::Texture streakTexture_;
    std::size_t streakTextureBytes_ = 0;
};

}  // namespace prism::rain
