// Table 2, the rate interpolation, validation and the particle-count formula
// (see prism/rain/rain_params.hpp).
#include "prism/rain/rain_params.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <sstream>

#include "prism/rain/random.hpp"
#include "prism/rain/rain_simulation.hpp"

namespace prism::rain {
namespace {

std::string str(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

[[noreturn]] void fail(const std::string& what) {
    throw RainParameterError("rain: " + what);
}

void requireFinite(float v, const char* name, const char* range) {
    if (!std::isfinite(v)) fail(std::string(name) + " must be a finite number " + range + " (got " + str(v) + ")");
}

}  // namespace

void validateIntensity(float intensity) {
    if (!std::isfinite(intensity) || intensity < 0.0f)
        fail("intensity must be a finite number >= 0 cm/h (Table 2: drizzle 0.0254 ... cloudburst 10.16; got " +
             str(intensity) + ")");
}

RainClass nearestRainClass(float intensity) {
    validateIntensity(intensity);
    const float li = std::log(std::max(intensity, 1e-6f));
    RainClass best = rainClasses().front().id;
    float bestDistance = INFINITY;
    for (const auto& c : rainClasses()) {
        const float d = std::fabs(std::log(c.intensity) - li);
        if (d < bestDistance) {
            bestDistance = d;
            best = c.id;
        }
    }
    return best;
}

RainRate rainRateFor(float intensity) {
    validateIntensity(intensity);
    const auto& first = rainClasses().front();
    const auto& last = rainClasses().back();
    if (intensity <= first.intensity)
        return {first.fallSpeed, first.dropsPerSquareMetreSecond * intensity / first.intensity};
    if (intensity >= last.intensity)
        return {last.fallSpeed, last.dropsPerSquareMetreSecond * intensity / last.intensity};
    for (std::size_t i = 0; i + 1 < rainClasses().size(); ++i) {
        const auto& a = rainClasses()[i];
        const auto& b = rainClasses()[i + 1];
        if (intensity <= b.intensity) {
            const float t =
                (std::log(intensity) - std::log(a.intensity)) / (std::log(b.intensity) - std::log(a.intensity));
            return {a.fallSpeed + t * (b.fallSpeed - a.fallSpeed),
                    a.dropsPerSquareMetreSecond + t * (b.dropsPerSquareMetreSecond - a.dropsPerSquareMetreSecond)};
        }
    }
    return {last.fallSpeed, last.dropsPerSquareMetreSecond};
}

void validateWind(const WindParams& wind) {
    if (!std::isfinite(wind.strength) || wind.strength < 0.0f)
        fail("wind strength must be a finite number >= 0 m/s (got " + str(wind.strength) + ")");
    if (wind.directionDegrees && !std::isfinite(*wind.directionDegrees))
        fail("wind direction must be a finite angle in degrees (got " + str(*wind.directionDegrees) + ")");
}

void validate(const RainParams& p) {
    validateIntensity(p.intensity);
    validateWind(p.wind);
    requireFinite(p.radius, "radius", "> 0 m");
    if (p.radius <= 0.0f || p.radius > 1.0e4f) fail("radius must be in (0, 10000] m (got " + str(p.radius) + ")");
    requireFinite(p.height, "height", "> 0 m");
    if (p.height <= 0.0f || p.height > 1.0e4f) fail("height must be in (0, 10000] m (got " + str(p.height) + ")");
    requireFinite(p.below, "below", "in [0, height]");
    if (p.below < 0.0f || p.below > p.height)
        fail("below must be in [0, height = " + str(p.height) + "] m (got " + str(p.below) + ")");
    if (p.groundHeight && !std::isfinite(*p.groundHeight))
        fail("groundHeight must be a finite height in m (got " + str(*p.groundHeight) + ")");
    if (p.lodRings < 1 || p.lodRings > 16) fail("lodRings must be in 1..16 (got " + std::to_string(p.lodRings) + ")");
    requireFinite(p.lodFalloff, "lodFalloff", "in (0, 1]");
    if (p.lodFalloff <= 0.0f || p.lodFalloff > 1.0f)
        fail("lodFalloff must be in (0, 1] (got " + str(p.lodFalloff) + ")");
    requireFinite(p.particlesPerDrop, "particlesPerDrop", "in (0, 1]");
    if (p.particlesPerDrop <= 0.0f || p.particlesPerDrop > 1.0f)
        fail("particlesPerDrop must be in (0, 1] (got " + str(p.particlesPerDrop) + ")");
    if (p.budget > kMaxParticles)
        fail("budget must be at most 2^24 = " + std::to_string(kMaxParticles) + " particles (got " +
             std::to_string(p.budget) + ")");
    if (p.fixedCount && *p.fixedCount > kMaxParticles)
        fail("fixedCount must be at most 2^24 = " + std::to_string(kMaxParticles) + " particles (got " +
             std::to_string(*p.fixedCount) + ")");
    requireFinite(p.jitter, "jitter", ">= 0 m/s");
    if (p.jitter < 0.0f || p.jitter > 100.0f) fail("jitter must be in [0, 100] m/s (got " + str(p.jitter) + ")");
    const auto& s = p.streaks;
    requireFinite(s.exposure, "streaks.exposure", "> 0 s");
    if (s.exposure <= 0.0f || s.exposure > 1.0f)
        fail("streaks.exposure must be in (0, 1] s (got " + str(s.exposure) + ")");
    requireFinite(s.width, "streaks.width", "> 0 m");
    requireFinite(s.widthPerMetre, "streaks.widthPerMetre", ">= 0");
    if (s.width <= 0.0f || s.widthPerMetre < 0.0f)
        fail("streaks.width must be > 0 and streaks.widthPerMetre >= 0 (got " + str(s.width) + ", " +
             str(s.widthPerMetre) + ")");
    requireFinite(s.opacity, "streaks.opacity", "in [0, 1]");
    if (s.opacity < 0.0f || s.opacity > 1.0f) fail("streaks.opacity must be in [0, 1] (got " + str(s.opacity) + ")");
    requireFinite(s.falloffDistance, "streaks.falloffDistance", "> 0 m");
    if (s.falloffDistance <= 0.0f) fail("streaks.falloffDistance must be > 0 m (got " + str(s.falloffDistance) + ")");
}

double lodWeightedArea(float radius, int rings, float falloff) {
    const double ringWidth = static_cast<double>(radius) / rings;
    double area = 0.0, w = 1.0;
    for (int k = 0; k < rings; ++k) {
        area += w * 3.14159265358979323846 * ringWidth * ringWidth * (2.0 * k + 1.0);
        w *= falloff;
    }
    return area;
}

double expectedParticleCount(const RainParams& p) {
    validate(p);
    const RainRate rate = rainRateFor(p.intensity);
    return static_cast<double>(p.particlesPerDrop) * rate.dropsPerCubicMetre() * p.height *
           lodWeightedArea(p.radius, p.lodRings, p.lodFalloff);
}

std::uint32_t particleCountFor(const RainParams& p) {
    const double expected = expectedParticleCount(p);  // validates
    if (p.fixedCount) return *p.fixedCount;
    const double capped = std::min<double>(std::round(expected), std::min(p.budget, kMaxParticles));
    return static_cast<std::uint32_t>(capped);
}

glm::vec3 windVector(const RainParams& p) {
    validateWind(p.wind);
    const float degrees = p.wind.directionDegrees ? *p.wind.directionDegrees
                                                  : 360.0f * rainUniform(p.seed, 0xFFFFFFFFu, kChannelWindDirection);
    const float radians = degrees * 0.017453292519943295f;
    return {p.wind.strength * std::cos(radians), 0.0f, p.wind.strength * std::sin(radians)};
}

glm::vec3 cylinderCenter(const RainParams& p, const glm::vec3& eye) {
    float bottom = eye.y - p.below;
    if (p.groundHeight) bottom = std::min(bottom, *p.groundHeight);
    return {eye.x, bottom + 0.5f * p.height, eye.z};
}

float shearHeight(const RainParams& p, const glm::vec3& eye) {
    return eye.y - cylinderCenter(p, eye).y;
}

std::string_view techniqueName(StreakTechnique t) {
    switch (t) {
        case StreakTechnique::GeometryShader: return "gs-quads";
        case StreakTechnique::Instanced: return "instanced-quads";
        case StreakTechnique::PointSprites: return "point-sprites";
    }
    return "?";
}

std::optional<StreakTechnique> parseTechnique(std::string_view name) {
    std::string n;
    for (char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (n == "gs" || n == "gs-quads" || n == "geometry") return StreakTechnique::GeometryShader;
    if (n == "instanced" || n == "instanced-quads") return StreakTechnique::Instanced;
    if (n == "points" || n == "point-sprites" || n == "sprites") return StreakTechnique::PointSprites;
    return std::nullopt;
}

}  // namespace prism::rain
