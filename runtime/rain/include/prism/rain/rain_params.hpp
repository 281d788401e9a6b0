// What a rain system is asked to simulate and draw: intensity (Table 2, rain_classes.hpp), the
// cylinder around the camera with its level-of-detail rings, wind, jitter, the
// particle budget and the streak style; plus the particle-count formula.
//
// Usage (snippet: examples/snippets/rain_rain_params.cpp):
//
//     #include "prism/rain/rain_params.hpp"
//     prism::rain::RainParams p;  // moderate rain
//     p.intensity = prism::rain::rainClassInfo(prism::rain::RainClass::Heavy).intensity;
//     p.wind.strength = 4.0f;                              // m/s, random direction
//     prism::rain::validate(p);                            // throws RainParameterError
//     std::uint32_t n = prism::rain::particleCountFor(p);  // 41,933 (heavy, defaults)
//
// Particle count (docs/rain.md): a rain of intensity I has a drop flux N(I) (drops per m^2
// per second) falling at v(I) m/s, so the air holds N/v drops per m^3. The cylinder's
// rings have relative densities falloff^k, so it holds as many drops as a volume of
//     V_LOD = height * sum_k falloff^k * area_k,   area_k = pi (R/K)^2 (2k + 1)
// at full density, and the count is
//     count = min(budget, round(particlesPerDrop * N(I) / v(I) * V_LOD))
// (fixedCount replaces the formula; the hard maximum is kMaxParticles = 2^24).
// N and v are interpolated between the Table 2 rows linearly in log(intensity); below
// drizzle N falls linearly to 0 at intensity 0, above cloudburst N grows in proportion.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "prism/rain/rain_classes.hpp"

namespace prism::rain {

// Thrown for parameters outside their documented ranges (negative intensity, NaN
// wind, ...); the message names the parameter, the value and the allowed range.
class RainParameterError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

// The class whose intensity is nearest in log scale (for display); throws for bad intensity.
RainClass nearestRainClass(float intensity);

// Fall speed and drop flux of a rain of `intensity` cm/h (see the formula above).
struct RainRate {
    float fallSpeed = 0.0f;                  // m/s
    float dropsPerSquareMetreSecond = 0.0f;  // N
    float dropsPerCubicMetre() const { return fallSpeed > 0.0f ? dropsPerSquareMetreSecond / fallSpeed : 0.0f; }
};
RainRate rainRateFor(float intensity);

struct WindParams {
    std::optional<float> directionDegrees;  // where the wind blows to, in the xz plane: 0 = +x, 90 = +z;
                                            // nullopt: random from the rain seed
    float strength = 0.0f;                  // m/s, >= 0
};

// How streaks are drawn (prism/rain/rain_system.hpp): quads from a geometry shader, instanced
// quads, or point sprites. Plain data here, so a scene can name one without a GL context.
enum class StreakTechnique { GeometryShader, Instanced, PointSprites };
std::string_view techniqueName(StreakTechnique t);                     // "gs-quads", "instanced-quads", "point-sprites"
std::optional<StreakTechnique> parseTechnique(std::string_view name);  // also "gs", "instanced", "points"

// How streaks look (used when drawing only).
struct StreakStyle {
    float exposure = 1.0f / 30.0f;  // s: streak length = speed x exposure
    float width = 0.004f;           // m at distance 0
    float widthPerMetre = 0.0015f;  // m of extra width per m of distance (seed: wider far away)
    float opacity = 0.9f;           // of a drop at distance 0
    float falloffDistance = 10.0f;  // m: opacity / (1 + (d / falloff)^2), Tariq's 1/d^2
};

inline constexpr std::uint32_t kMaxParticles = 1u << 24;

struct RainParams {
    float intensity = 0.381f;                 // cm/h (Table 2 corrected: moderate); 0 = no drops
    float radius = 25.0f;                     // m, cylinder around the camera
    float height = 20.0f;                     // m
    float below = 4.0f;                       // m of the cylinder below the camera, in [0, height]
    std::optional<float> groundHeight;        // world y of the lowest ground under the cylinder: the
                                              // bottom reaches down to it (min(eye.y - below, ground))
    int lodRings = 4;                         // level-of-detail rings K, 1..16
    float lodFalloff = 0.5f;                  // density of ring k relative to the centre: falloff^k, (0, 1]
    float particlesPerDrop = 0.05f;           // particles per physical drop, (0, 1]
    std::uint32_t budget = 1u << 18;          // user cap on the particle count, <= kMaxParticles
    std::optional<std::uint32_t> fixedCount;  // replaces the formula (benchmarks), <= kMaxParticles
    float jitter = 0.3f;                      // m/s: largest random sideways speed of a drop, >= 0
    WindParams wind;
    std::uint32_t seed = 1;
    StreakStyle streaks;
};

// Throws RainParameterError naming the first bad field.
void validate(const RainParams& params);
void validateIntensity(float intensity);
void validateWind(const WindParams& wind);

// The relative volume V_LOD / height: sum over rings of falloff^k * area_k (m^2).
double lodWeightedArea(float radius, int rings, float falloff);
// particlesPerDrop * N/v * V_LOD, before rounding and the caps.
double expectedParticleCount(const RainParams& params);
// The particle count the system simulates (validates first).
std::uint32_t particleCountFor(const RainParams& params);
// The wind velocity (m/s, y = 0); a missing direction comes from params.seed.
glm::vec3 windVector(const RainParams& params);
// The centre of the cylinder for a camera at `eye`: bottom + height / 2 with
// bottom = eye.y - below, lowered to groundHeight when that is lower, so the rain always
// reaches the ground (docs/rain.md, "Cylinder").
glm::vec3 cylinderCenter(const RainParams& params, const glm::vec3& eye);
// The height relative to the cylinder centre at which the wind shear is zero: the eye's,
// so the drops at eye height stand in their seed columns around the camera.
float shearHeight(const RainParams& params, const glm::vec3& eye);

}  // namespace prism::rain
