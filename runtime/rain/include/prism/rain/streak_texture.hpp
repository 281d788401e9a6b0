// The procedural rain-streak texture array that replaces the Garg & Nayar streak
// database (which cannot be downloaded here), laid out as in Tariq's NVIDIA "Rain":
// 5 vertical light angles theta x 9 horizontal light-eye angles phi x 10 drop
// oscillation types = 450 layers of R8, each `width` x `height` texels (u across the
// streak, v along it from the drop's head at v = 0 to its tail at v = 1).
//
// Usage (snippet: examples/snippets/rain_streak_texture.cpp):
//
//     #include "prism/rain/streak_texture.hpp"
//     prism::rain::StreakTextureArray tex = prism::rain::generateStreakTextures();
//     int layer = prism::rain::streakLayer(/*oscillation*/ 3, /*theta bin*/ 2, /*phi bin*/ 8);
//     std::uint8_t t = tex.at(layer, 8, 32);
//
// The model (docs/rain.md, "Streak texture model"), for a light at (theta, phi) seen
// from the side (theta_view = 90 deg, as RainCL §4.1.4 also assumed):
//   scattering angle alpha = acos(-sin(theta) cos(phi)), 0 = light straight behind the drop;
//   brightness B = 0.10 (sky) + 0.70 exp(-(alpha/50)^2)      refraction: the drop as a lens
//                + 0.30 exp(-((alpha-138)/6)^2)               primary-rainbow internal reflection
//                + 0.25 F((180 - alpha)/2)                    external reflection, Schlick F0 = 0.02
//   along the streak (the exposure): B (1 - A + A c(v)) + glint g^k with
//     c(v) = (1 + cos(2 pi f v + psi)) / 2 from the oscillation type (f cycles, amplitude A,
//     phase psi, sharpness k), the glint phase shifted by the light angles;
//   across: a Gaussian (sigma 0.16) around a centre that sways with the oscillation and
//     sits towards the lit side; soft ends over the first and last 10 %.
// Nothing here needs GL; RainSystem uploads the array as GL_TEXTURE_2D_ARRAY.
#pragma once

#include <cstdint>
#include <vector>

namespace prism::rain {

inline constexpr int kThetaBins = 5;
inline constexpr int kPhiBins = 9;
inline constexpr int kOscillationTypes = 10;
inline constexpr int kStreakLayers = kThetaBins * kPhiBins * kOscillationTypes;  // 450

constexpr int streakLayer(int oscillation, int thetaBin, int phiBin) {
    return (oscillation * kThetaBins + thetaBin) * kPhiBins + phiBin;
}
// Bin centres in degrees: theta 10, 50, 90, 130, 170; phi 10, 30, ..., 170.
constexpr float thetaOfBin(int bin) {
    return 10.0f + 40.0f * static_cast<float>(bin);
}
constexpr float phiOfBin(int bin) {
    return 10.0f + 20.0f * static_cast<float>(bin);
}

struct OscillationType {
    float frequency;  // brightness cycles along one streak
    float amplitude;  // of the brightness modulation, in [0, 1]
    float phase;      // radians
    float sharpness;  // exponent of the glint peaks
    float sway;       // sideways wobble of the streak centre, in u
    float side;       // +1 or -1: which side the lit spot sits on
};
OscillationType oscillationType(int type);  // 0..9, fixed (hash of the type)

// Scattering angle (degrees) between the light's travel and the way to the eye.
float scatteringAngle(float thetaDegrees, float phiDegrees);
// B(theta, phi) above, in [0, 1].
float streakBrightness(float thetaDegrees, float phiDegrees);
// The texel value in [0, 1] before quantisation; u, v in [0, 1].
float streakValue(int oscillation, float thetaDegrees, float phiDegrees, float u, float v);

struct StreakTextureArray {
    int width = 0;
    int height = 0;
    int layers = 0;
    std::vector<std::uint8_t> texels;  // layer-major, then rows (v), then u

    std::uint8_t at(int layer, int x, int y) const {
        return texels[(static_cast<std::size_t>(layer) * static_cast<std::size_t>(height) +
                       static_cast<std::size_t>(y)) *
                          static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
    double layerMean(int layer) const;  // 0..255
    std::size_t bytes() const { return texels.size(); }
};

// Throws std::invalid_argument for sizes outside 2..1024.
// The same array packed for one texture fetch per light (rainStreakTexel in
// modules/rain/streak_lighting.glsl): RGBA8, layer (oscillation, theta bin b, phi bin c) holds
// the R8 layers (b, c), (b, c + 1), (b + 1, c), (b + 1, c + 1) in R, G, B, A, the neighbours
// clamped to the last bin, so a linearly filtered fetch gives the four corners of the bilinear
// blend between bins exactly as four R8 fetches did. width x height x layers x 4 bytes.
std::vector<std::uint8_t> packStreakBinCorners(const StreakTextureArray& t);

StreakTextureArray generateStreakTextures(int width = 16, int height = 64);

}  // namespace prism::rain
