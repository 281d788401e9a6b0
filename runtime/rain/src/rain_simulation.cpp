// The CPU reference of the rain simulation: a line-by-line mirror of
// modules/rain/particles.glsl (see prism/rain/rain_simulation.hpp).
#include "prism/rain/rain_simulation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "prism/rain/random.hpp"

namespace prism::rain {
namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

std::string str(const glm::vec3& v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

glm::vec2 windShear(glm::vec2 seedXZ, const glm::vec3& wind, float y, float shearHeight, float fallSpeed) {
    return seedXZ - glm::vec2(wind.x, wind.z) * ((y - shearHeight) / fallSpeed);
}

}  // namespace

float clampStep(float dt) {
    if (std::isnan(dt) || dt < 0.0f) {
        std::ostringstream s;
        s << "rain: the time step must be a number >= 0 s (got " << dt << ")";
        throw RainParameterError(s.str());
    }
    return std::min(dt, kMaxStepSeconds);
}

void validateEye(const glm::vec3& eye) {
    if (!std::isfinite(eye.x) || !std::isfinite(eye.y) || !std::isfinite(eye.z))
        throw RainParameterError("rain: the camera position must be finite (got " + str(eye) + ")");
}

glm::vec2 foldIntoCylinder(glm::vec2 xz, glm::vec2 seedXZ, float radius) {
    const float r = std::sqrt(xz.x * xz.x + xz.y * xz.y);
    if (r <= radius) return xz;
    if (r < 3.0f * radius) return xz * ((r - 2.0f * radius) / r);
    return seedXZ;
}

Particle seedParticle(std::uint32_t index, std::uint32_t seed, const glm::vec3& center, const glm::vec2& cylinder,
                      const glm::vec2& lod, float fallSpeed, float jitter, const glm::vec3& wind, float shearHeight) {
    const float R = cylinder.x;
    const float H = cylinder.y;
    const int rings = static_cast<int>(lod.x);
    float total = 0.0f;
    float w = 1.0f;
    for (int k = 0; k < rings; ++k) {
        total += w * static_cast<float>(2 * k + 1);
        w *= lod.y;
    }
    const float pick = rainUniform(seed, index, kChannelRing) * total;
    int ring = rings - 1;
    float acc = 0.0f;
    w = 1.0f;
    for (int k = 0; k < rings; ++k) {
        acc += w * static_cast<float>(2 * k + 1);
        if (pick < acc) {
            ring = k;
            break;
        }
        w *= lod.y;
    }
    const float fk = static_cast<float>(ring);
    float r = (R / static_cast<float>(rings)) *
              std::sqrt(fk * fk + rainUniform(seed, index, kChannelRadius) * (2.0f * fk + 1.0f));
    r = std::min(r, R);
    const float angle = kTwoPi * rainUniform(seed, index, kChannelAngle);
    const float y = (rainUniform(seed, index, kChannelHeight) - 0.5f) * H;
    const float speedFactor = 0.9f + 0.2f * rainUniform(seed, index, kChannelSpeed);

    Particle p;
    p.seed = glm::vec4(r * std::cos(angle), y, r * std::sin(angle), rainUniform(seed, index, kChannelOscillation));
    const float v = fallSpeed * speedFactor;
    p.velocity = glm::vec4(jitter * (2.0f * rainUniform(seed, index, kChannelJitterX) - 1.0f), -v,
                           jitter * (2.0f * rainUniform(seed, index, kChannelJitterZ) - 1.0f), speedFactor);
    const glm::vec2 seedXZ(p.seed.x, p.seed.z);
    const glm::vec2 xz = foldIntoCylinder(windShear(seedXZ, wind, y, shearHeight, v), seedXZ, R);
    p.position = glm::vec4(center + glm::vec3(xz.x, y, xz.y), rainUniform(seed, index, kChannelBrightness));
    return p;
}

Particle stepParticle(Particle p, const StepInputs& in) {
    const float R = in.cylinder.x;
    const float H = in.cylinder.y;
    const float halfH = 0.5f * H;
    const glm::vec3 pos = glm::vec3(p.position) + (glm::vec3(p.velocity) + in.wind) * in.dt;
    glm::vec3 local = pos - in.center;
    const glm::vec2 seedXZ(p.seed.x, p.seed.z);
    glm::vec2 xz(local.x, local.z);
    if (local.y < -halfH) {
        local.y -= H * std::floor((local.y + halfH) / H);
        const float v = in.fallSpeed * p.velocity.w;
        p.velocity.y = -v;
        xz = windShear(seedXZ, in.wind, local.y, in.shearHeight, v);
    } else if (local.y >= halfH) {
        local.y -= H * std::floor((local.y + halfH) / H);
    }
    xz = foldIntoCylinder(xz, seedXZ, R);
    p.position = glm::vec4(in.center + glm::vec3(xz.x, local.y, xz.y), p.position.w);
    return p;
}

int lodRingOf(const Particle& p, float radius, int rings) {
    const float r = std::sqrt(p.seed.x * p.seed.x + p.seed.z * p.seed.z);
    return std::clamp(static_cast<int>(r / radius * static_cast<float>(rings)), 0, rings - 1);
}

RainWeather::RainWeather(const RainParams& p) : params(p) {
    validate(params);
    rate = rainRateFor(params.intensity);
    wind = windVector(params);
}

void RainWeather::setIntensity(float intensity) {
    validateIntensity(intensity);
    params.intensity = intensity;
    rate = rainRateFor(intensity);
}

void RainWeather::setWind(const WindParams& w) {
    validateWind(w);
    params.wind = w;
    wind = windVector(params);
}

CpuRainSimulation::CpuRainSimulation(const RainParams& params, const glm::vec3& eye) : weather_(params) {
    validateEye(eye);
    center_ = cylinderCenter(weather_.params, eye);
    shearHeight_ = shearHeight(weather_.params, eye);
    resize(particleCountFor(weather_.params));
}

void CpuRainSimulation::resize(std::uint32_t count) {
    if (count > particles_.size()) particles_.resize(count);
    const glm::vec2 cylinder(weather_.params.radius, weather_.params.height);
    const glm::vec2 lod(static_cast<float>(weather_.params.lodRings), weather_.params.lodFalloff);
    for (std::uint32_t i = count_; i < count; ++i)
        particles_[i] = seedParticle(i, weather_.params.seed, center_, cylinder, lod, weather_.rate.fallSpeed,
                                     weather_.params.jitter, weather_.wind, shearHeight_);
    count_ = count;
}

void CpuRainSimulation::step(float dt, const glm::vec3& eye) {
    validateEye(eye);
    StepInputs in;
    in.dt = clampStep(dt);
    center_ = cylinderCenter(weather_.params, eye);
    shearHeight_ = shearHeight(weather_.params, eye);
    in.center = center_;
    in.shearHeight = shearHeight_;
    in.cylinder = {weather_.params.radius, weather_.params.height};
    in.wind = weather_.wind;
    in.fallSpeed = weather_.rate.fallSpeed;
    for (std::uint32_t i = 0; i < count_; ++i) particles_[i] = stepParticle(particles_[i], in);
}

void CpuRainSimulation::setIntensity(float intensity) {
    weather_.setIntensity(intensity);
    resize(particleCountFor(weather_.params));
}

void CpuRainSimulation::setWind(const WindParams& wind) {
    weather_.setWind(wind);
}

}  // namespace prism::rain
