// view::Fog parameters, the animated noise array and the billboard motion
// (see prism/rain/fog_billboards.hpp).
#include "prism/rain/fog_billboards.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_simulation.hpp"
#include "prism/rain/random.hpp"

namespace prism::rain {
namespace {

[[noreturn]] void fail(const std::string& field, float value, const std::string& range) {
    std::ostringstream s;
    s << "rain: fog " << field << " must be " << range << " (got " << value << ")";
    throw RainParameterError(s.str());
}

float fade(float t) {
    return t * t * (3.0f - 2.0f * t);
}

// Periodic value noise: lattice values from the hash, wrapped with the periods.
float valueNoise(float x, float y, float z, int period, int periodZ, std::uint32_t seed, std::uint32_t octave) {
    const int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y)),
              iz = static_cast<int>(std::floor(z));
    const float fx = fade(x - static_cast<float>(ix)), fy = fade(y - static_cast<float>(iy)),
                fz = fade(z - static_cast<float>(iz));
    auto lattice = [&](int a, int b, int c) {
        const auto wrap = [](int v, int p) { return static_cast<std::uint32_t>(((v % p) + p) % p); };
        const std::uint32_t index =
            wrap(a, period) + static_cast<std::uint32_t>(period) *
                                  (wrap(b, period) + static_cast<std::uint32_t>(period) * wrap(c, periodZ));
        return rainUniform(seed, index, 20u + octave);
    };
    float v[2][2][2];
    for (int c = 0; c < 2; ++c)
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) v[c][b][a] = lattice(ix + a, iy + b, iz + c);
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    const float z0 = lerp(lerp(v[0][0][0], v[0][0][1], fx), lerp(v[0][1][0], v[0][1][1], fx), fy);
    const float z1 = lerp(lerp(v[1][0][0], v[1][0][1], fx), lerp(v[1][1][0], v[1][1][1], fx), fy);
    return lerp(z0, z1, fz);
}

}  // namespace

SceneFog fogOverGround(const view::Fog& distance, float strength, float groundHeight) {
    SceneFog fog;
    fog.distance = distance;
    fog.billboards.strength = strength;
    fog.billboards.color = distance.color;
    fog.billboards.groundHeight = groundHeight;
    fog.billboards.minHeight = groundHeight + 0.5f;
    fog.billboards.maxHeight = groundHeight + 4.0f;
    return fog;
}

void validate(const SceneFog& fog) {
    if (!(fog.distance.density >= 0.0f) || !std::isfinite(fog.distance.density))
        fail("density", fog.distance.density, "a finite number >= 0 per metre");
    const auto& b = fog.billboards;
    if (!(b.strength >= 0.0f && b.strength <= 1.0f)) fail("billboard strength", b.strength, "in [0, 1]");
    if (b.count < 1 || b.count > 4096) fail("billboard count", static_cast<float>(b.count), "in 1..4096");
    if (!(b.size > 0.0f) || !std::isfinite(b.size)) fail("billboard size", b.size, "a finite number > 0 m");
    if (!(b.radius > 0.0f) || !std::isfinite(b.radius)) fail("billboard radius", b.radius, "a finite number > 0 m");
    if (!std::isfinite(b.minHeight) || !std::isfinite(b.maxHeight) || b.maxHeight < b.minHeight)
        fail("billboard maxHeight", b.maxHeight, "finite and >= minHeight");
    if (!(b.drift >= 0.0f) || !std::isfinite(b.drift)) fail("billboard drift", b.drift, "a finite number >= 0 m/s");
    if (!(b.windFactor >= 0.0f) || !std::isfinite(b.windFactor))
        fail("billboard windFactor", b.windFactor, "a finite number >= 0");
    if (!std::isfinite(b.groundHeight)) fail("billboard groundHeight", b.groundHeight, "a finite height in m");
    if (!(b.softDistance > 0.0f) || !std::isfinite(b.softDistance))
        fail("billboard softDistance", b.softDistance, "a finite number > 0 m");
    for (float c : {b.color.r, b.color.g, b.color.b, fog.distance.color.r, fog.distance.color.g, fog.distance.color.b})
        if (!std::isfinite(c) || c < 0.0f) fail("colour channel", c, "a finite number >= 0");
}

FogNoiseArray generateFogNoise(int size, int layers, std::uint32_t seed) {
    if (size < 4 || size > 1024 || layers < 1 || layers > 256)
        throw std::invalid_argument("rain: fog noise must be 4..1024 texels and 1..256 layers (got " +
                                    std::to_string(size) + ", " + std::to_string(layers) + ")");
    FogNoiseArray n;
    n.size = size;
    n.layers = layers;
    n.texels.resize(static_cast<std::size_t>(size) * size * layers);
    constexpr int kOctaves = 4;
    constexpr int kTimeCells = 4;  // lattice cells through one loop of the animation
    for (int l = 0; l < layers; ++l)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                float sum = 0.0f, norm = 0.0f, amplitude = 1.0f;
                for (int o = 0; o < kOctaves; ++o) {
                    const int cells = 4 << o;
                    const float fx = static_cast<float>(x) / static_cast<float>(size) * static_cast<float>(cells);
                    const float fy = static_cast<float>(y) / static_cast<float>(size) * static_cast<float>(cells);
                    const float fz =
                        static_cast<float>(l) / static_cast<float>(layers) * static_cast<float>(kTimeCells);
                    sum += amplitude * valueNoise(fx, fy, fz, cells, kTimeCells, seed, static_cast<std::uint32_t>(o));
                    norm += amplitude;
                    amplitude *= 0.5f;
                }
                const float v = sum / norm;
                const float t = std::clamp((v - 0.3f) / 0.45f, 0.0f, 1.0f);
                n.texels[(static_cast<std::size_t>(l) * size + y) * size + x] =
                    static_cast<std::uint8_t>(std::lround(fade(t) * 255.0f));
            }
    return n;
}

FogBillboardSimulation::FogBillboardSimulation(const FogBillboardParams& params, const glm::vec3& eye)
    : params_(params) {
    SceneFog check;
    check.billboards = params;
    validate(check);
    validateEye(eye);
    const auto u = [&](std::uint32_t i, std::uint32_t c) { return rainUniform(params_.seed, i, 40u + c); };
    for (int i = 0; i < params_.count; ++i) {
        const auto idx = static_cast<std::uint32_t>(i);
        const float r = params_.radius * std::sqrt(u(idx, 0));
        const float a = 6.2831853f * u(idx, 1);
        const float h = params_.minHeight + (params_.maxHeight - params_.minHeight) * u(idx, 2);
        billboards_.emplace_back(eye.x + r * std::cos(a), h, eye.z + r * std::sin(a), u(idx, 3));
        const float da = 6.2831853f * u(idx, 4);
        drift_.emplace_back(params_.drift * std::cos(da), 0.0f, params_.drift * std::sin(da));
    }
}

void FogBillboardSimulation::step(float dt, const glm::vec3& eye, const glm::vec3& wind) {
    validateEye(eye);
    const float h = clampStep(dt);
    for (std::size_t i = 0; i < billboards_.size(); ++i) {
        glm::vec3 p =
            glm::vec3(billboards_[i]) + (drift_[i] + params_.windFactor * glm::vec3(wind.x, 0.0f, wind.z)) * h;
        glm::vec2 local(p.x - eye.x, p.z - eye.z);
        local = foldIntoCylinder(local, glm::vec2(0.0f), params_.radius);
        billboards_[i] = glm::vec4(eye.x + local.x, p.y, eye.z + local.y, billboards_[i].w);
    }
}

}  // namespace prism::rain
