// The procedural sky cube map and capillary-ripple frames (see procedural_textures.hpp).
#include "prism/water/procedural_textures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "prism/water/height_field.hpp"

namespace prism::water {
namespace {

constexpr float kPi = 3.14159265358979f;

std::uint8_t toByte(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) {
    return a + (b - a) * t;
}

}  // namespace

glm::vec3 skyDirection(int face, int s, int t, int size) {
    const float sc = 2.0f * (static_cast<float>(s) + 0.5f) / static_cast<float>(size) - 1.0f;
    const float tc = 2.0f * (static_cast<float>(t) + 0.5f) / static_cast<float>(size) - 1.0f;
    glm::vec3 d;
    switch (face) {
        case 0: d = {1.0f, -tc, -sc}; break;
        case 1: d = {-1.0f, -tc, sc}; break;
        case 2: d = {sc, 1.0f, tc}; break;
        case 3: d = {sc, -1.0f, -tc}; break;
        case 4: d = {sc, -tc, 1.0f}; break;
        default: d = {-sc, -tc, -1.0f}; break;
    }
    return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

glm::vec3 skyRadiance(const glm::vec3& d, const SkyOptions& o) {
    const float elevation = d.y;
    if (elevation < 0.0f) return mix(o.horizon * 0.85f, o.ground, smoothstep(0.02f, 0.5f, -elevation));
    glm::vec3 sky = mix(o.horizon, o.zenith, std::pow(smoothstep(0.0f, 1.0f, elevation), 0.6f));
    // Clouds: fBm on the direction projected onto a cloud layer (flattened near the horizon).
    const float scale = 1.0f / (elevation + 0.15f);
    const float cx = d.x * scale * 1.2f, cz = d.z * scale * 1.2f;
    const float n = fbm3(cx + 10.0f, cz - 3.0f, 0.37f, o.seed, 6);
    const float cover = smoothstep(1.0f - o.cloudCover - 0.05f, 1.0f - o.cloudCover + 0.25f, n);
    // Darker, heavier cloud bases and brighter tops, all fading into haze at the horizon.
    const float shade = fbm3(cx * 2.0f + 4.0f, cz * 2.0f, 2.1f, o.seed + 17U, 4);
    const glm::vec3 cloud =
        mix(glm::vec3(0.47f, 0.49f, 0.52f), glm::vec3(0.86f, 0.87f, 0.88f), smoothstep(0.3f, 0.75f, shade));
    const float haze = smoothstep(0.0f, 0.12f, elevation);
    return mix(sky, cloud, cover * (0.35f + 0.65f * haze));
}

CubeFaces proceduralSky(const SkyOptions& o) {
    if (o.faceSize < 1 || o.faceSize > 4096) throw std::invalid_argument("proceduralSky: faceSize must be in 1..4096");
    CubeFaces faces;
    faces.size = o.faceSize;
    for (int f = 0; f < 6; ++f) {
        auto& px = faces.rgba[static_cast<std::size_t>(f)];
        px.resize(static_cast<std::size_t>(o.faceSize) * o.faceSize * 4);
        for (int t = 0; t < o.faceSize; ++t)
            for (int s = 0; s < o.faceSize; ++s) {
                const glm::vec3 c = skyRadiance(skyDirection(f, s, t, o.faceSize), o);
                const std::size_t i = (static_cast<std::size_t>(t) * o.faceSize + s) * 4;
                px[i] = toByte(c.x);
                px[i + 1] = toByte(c.y);
                px[i + 2] = toByte(c.z);
                px[i + 3] = 255;
            }
    }
    return faces;
}

RippleFrames proceduralRipples(const RippleOptions& o) {
    if (o.size < 4 || o.size > 1024 || o.drops < 0)
        throw std::invalid_argument("proceduralRipples: size 4..1024, drops >= 0");
    RippleFrames out;
    out.size = o.size;
    const int n = o.size;
    const int frames = RippleFrames::kFrames;
    out.rgba.resize(static_cast<std::size_t>(frames) * n * n * 4);
    struct Drop {
        float x, y, start, amplitude;
    };
    std::vector<Drop> drops;
    for (int k = 0; k < o.drops; ++k)
        drops.push_back({latticeNoise(k, 1, 5, o.seed), latticeNoise(k, 2, 5, o.seed), latticeNoise(k, 3, 5, o.seed),
                         0.6f + 0.4f * latticeNoise(k, 4, 5, o.seed)});
    std::vector<float> height(static_cast<std::size_t>(n) * n);
    const float maxRadius = 0.32f;  // of the tile, at the end of a drop's life
    const float wavelength = 0.045f;
    for (int f = 0; f < frames; ++f) {
        const float phase = static_cast<float>(f) / static_cast<float>(frames);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(n);
                const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(n);
                float h = 0.0f;
                for (const Drop& d : drops) {
                    const float age = phase - d.start - std::floor(phase - d.start);  // 0..1, cyclic
                    float dx = std::abs(u - d.x), dy = std::abs(v - d.y);
                    dx = std::min(dx, 1.0f - dx);  // wrap: the tile repeats
                    dy = std::min(dy, 1.0f - dy);
                    const float r = std::sqrt(dx * dx + dy * dy);
                    const float front = age * maxRadius;
                    const float behind = front - r;  // > 0 inside the ring front
                    if (behind < 0.0f || behind > 3.0f * wavelength) continue;
                    const float envelope = std::sin(kPi * behind / (3.0f * wavelength));
                    const float fade = (1.0f - age) * (1.0f - age);
                    h += d.amplitude * fade * envelope * std::cos(2.0f * kPi * behind / wavelength);
                }
                height[static_cast<std::size_t>(y) * n + x] = h;
            }
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                auto at = [&](int xx, int yy) {
                    return height[static_cast<std::size_t>((yy + n) % n) * n + static_cast<std::size_t>((xx + n) % n)];
                };
                const float gx = (at(x + 1, y) - at(x - 1, y)) * 0.5f;
                const float gy = (at(x, y + 1) - at(x, y - 1)) * 0.5f;
                glm::vec3 normal(-gx * 2.0f, -gy * 2.0f, 1.0f);
                normal /= std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
                const std::size_t i = ((static_cast<std::size_t>(f) * n + y) * n + x) * 4;
                out.rgba[i] = toByte(normal.x * 0.5f + 0.5f);
                out.rgba[i + 1] = toByte(normal.y * 0.5f + 0.5f);
                out.rgba[i + 2] = toByte(normal.z * 0.5f + 0.5f);
                out.rgba[i + 3] = toByte(at(x, y) * 0.5f + 0.5f);
            }
    }
    return out;
}

double rippleFramesPerSecond(double rainMmPerHour) {
    if (!(rainMmPerHour > 0.0)) return 0.0;
    return std::min(30.0, 6.0 + 2.0 * std::sqrt(rainMmPerHour));
}

float rippleDensity(double rainMmPerHour) {
    if (!(rainMmPerHour > 0.0)) return 0.0f;
    return static_cast<float>(std::clamp(1.0 + 0.5 * std::log2(rainMmPerHour), 0.5, 4.0));
}

float rippleStrength(double rainMmPerHour) {
    if (!(rainMmPerHour > 0.0)) return 0.0f;
    return static_cast<float>(std::min(1.0, 0.25 + 0.15 * std::log10(1.0 + rainMmPerHour) * 2.0));
}

}  // namespace prism::water
