// The procedural streak texture array (see prism/rain/streak_texture.hpp).
#include "prism/rain/streak_texture.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "prism/rain/random.hpp"

namespace prism::rain {
namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kDeg = kPi / 180.0f;
constexpr std::uint32_t kTextureSeed = 0x5EED57EAu;

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Schlick's Fresnel reflectance of water (F0 = 0.02) at incidence `degrees`.
float schlick(float degrees) {
    const float c = std::clamp(std::cos(degrees * kDeg), 0.0f, 1.0f);
    return 0.02f + 0.98f * std::pow(1.0f - c, 5.0f);
}

}  // namespace

OscillationType oscillationType(int type) {
    if (type < 0 || type >= kOscillationTypes)
        throw std::invalid_argument("rain: oscillation type must be in 0.." + std::to_string(kOscillationTypes - 1));
    const auto u = [type](std::uint32_t channel) {
        return rainUniform(kTextureSeed, static_cast<std::uint32_t>(type), channel);
    };
    OscillationType o;
    o.frequency = 1.0f + 3.0f * u(0);
    o.amplitude = 0.15f + 0.4f * u(1);
    o.phase = 2.0f * kPi * u(2);
    o.sharpness = 6.0f + 18.0f * u(3);
    o.sway = 0.04f * u(4);
    o.side = (type % 2 == 0) ? 1.0f : -1.0f;
    return o;
}

float scatteringAngle(float thetaDegrees, float phiDegrees) {
    const float c = -std::sin(thetaDegrees * kDeg) * std::cos(phiDegrees * kDeg);
    return std::acos(std::clamp(c, -1.0f, 1.0f)) / kDeg;
}

float streakBrightness(float thetaDegrees, float phiDegrees) {
    const float alpha = scatteringAngle(thetaDegrees, phiDegrees);
    const float refraction = std::exp(-(alpha / 50.0f) * (alpha / 50.0f));
    const float rainbow = std::exp(-((alpha - 138.0f) / 6.0f) * ((alpha - 138.0f) / 6.0f));
    const float reflection = schlick(0.5f * (180.0f - alpha));
    return std::clamp(0.10f + 0.70f * refraction + 0.30f * rainbow + 0.25f * reflection, 0.0f, 1.0f);
}

float streakValue(int oscillation, float thetaDegrees, float phiDegrees, float u, float v) {
    const OscillationType o = oscillationType(oscillation);
    const float alpha = scatteringAngle(thetaDegrees, phiDegrees);
    const float brightness = streakBrightness(thetaDegrees, phiDegrees);
    const float wave = 2.0f * kPi * o.frequency * v + o.phase;
    const float modulation = 1.0f - o.amplitude + o.amplitude * 0.5f * (1.0f + std::cos(wave));
    // Glints: the oscillating surface sends light to the eye at some phases; where
    // depends on the light's angles, how strongly on the reflection geometry.
    const float glintShift = 0.5f * thetaDegrees * kDeg + 0.25f * phiDegrees * kDeg;
    const float glintWave = 0.5f * (1.0f + std::cos(wave + glintShift));
    const float rainbow = std::exp(-((alpha - 138.0f) / 6.0f) * ((alpha - 138.0f) / 6.0f));
    const float forward = std::exp(-(alpha / 50.0f) * (alpha / 50.0f));
    const float glintStrength = 0.1f + 0.6f * std::max(rainbow, 0.6f * forward);
    const float along = brightness * modulation + glintStrength * std::pow(glintWave, o.sharpness);
    const float lit = std::sin(thetaDegrees * kDeg) * std::sin(phiDegrees * kDeg);
    const float center = 0.5f + o.side * 0.12f * lit + o.sway * std::sin(wave);
    const float sigma = 0.16f;
    const float across = std::exp(-0.5f * ((u - center) / sigma) * ((u - center) / sigma));
    const float ends = smoothstep(0.0f, 0.1f, v) * (1.0f - smoothstep(0.9f, 1.0f, v));
    return std::clamp(across * ends * along, 0.0f, 1.0f);
}

double StreakTextureArray::layerMean(int layer) const {
    double sum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) sum += at(layer, x, y);
    return sum / (static_cast<double>(width) * height);
}

std::vector<std::uint8_t> packStreakBinCorners(const StreakTextureArray& t) {
    const std::size_t layerTexels = static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
    std::vector<std::uint8_t> packed(4 * layerTexels * static_cast<std::size_t>(t.layers));
    for (int osc = 0; osc < kOscillationTypes; ++osc)
        for (int theta = 0; theta < kThetaBins; ++theta)
            for (int phi = 0; phi < kPhiBins; ++phi) {
                const int theta1 = std::min(theta + 1, kThetaBins - 1);
                const int phi1 = std::min(phi + 1, kPhiBins - 1);
                const int corners[4] = {streakLayer(osc, theta, phi), streakLayer(osc, theta, phi1),
                                        streakLayer(osc, theta1, phi), streakLayer(osc, theta1, phi1)};
                const std::size_t layer = static_cast<std::size_t>(streakLayer(osc, theta, phi));
                for (std::size_t texel = 0; texel < layerTexels; ++texel)
                    for (int c = 0; c < 4; ++c)
                        packed[4 * (layer * layerTexels + texel) + static_cast<std::size_t>(c)] =
                            t.texels[static_cast<std::size_t>(corners[c]) * layerTexels + texel];
            }
    return packed;
}

StreakTextureArray generateStreakTextures(int width, int height) {
    if (width < 2 || width > 1024 || height < 2 || height > 1024)
        throw std::invalid_argument("rain: streak texture size must be 2..1024 in each direction (got " +
                                    std::to_string(width) + "x" + std::to_string(height) + ")");
    StreakTextureArray t;
    t.width = width;
    t.height = height;
    t.layers = kStreakLayers;
    t.texels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * kStreakLayers);
    for (int o = 0; o < kOscillationTypes; ++o)
        for (int ti = 0; ti < kThetaBins; ++ti)
            for (int pj = 0; pj < kPhiBins; ++pj) {
                const int layer = streakLayer(o, ti, pj);
                for (int y = 0; y < height; ++y)
                    for (int x = 0; x < width; ++x) {
                        const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
                        const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
                        const float value = streakValue(o, thetaOfBin(ti), phiOfBin(pj), u, v);
                        t.texels[(static_cast<std::size_t>(layer) * height + y) * width + x] =
                            static_cast<std::uint8_t>(std::lround(value * 255.0f));
                    }
            }
    return t;
}

}  // namespace prism::rain
