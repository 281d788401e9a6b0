// Textures the water scene makes itself (no image files): the cloudy sky cube map of
// the skybox and the 16 capillary-ripple frames of the water surface (RainCL §4.3.2
// and §4.5). Pure CPU, deterministic for a random seed.
//
// Usage (snippet: examples/snippets/water_procedural_textures.cpp):
//
//     #include "prism/water/procedural_textures.hpp"
//     prism::water::CubeFaces sky = prism::water::proceduralSky({.faceSize = 128});
//     prism::water::RippleFrames ripples = prism::water::proceduralRipples({});
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace prism::water {

struct SkyOptions {
    int faceSize = 128;       // texels per cube face edge
    float cloudCover = 0.6f;  // 0 clear .. 1 overcast
    unsigned seed = 7;
    glm::vec3 zenith{0.34f, 0.42f, 0.52f};   // rain sky: grey-blue above
    glm::vec3 horizon{0.70f, 0.72f, 0.74f};  // pale grey at the horizon
    glm::vec3 ground{0.42f, 0.42f, 0.40f};   // below the horizon: hazy distant land
};

// RGBA8 faces in GL order +X, -X, +Y, -Y, +Z, -Z; texel (s, t) of a face, row t first,
// is the direction skyDirection(face, s, t, size) (the GL cube-map convention).
struct CubeFaces {
    int size = 0;
    std::array<std::vector<std::uint8_t>, 6> rgba;
};

glm::vec3 skyDirection(int face, int s, int t, int size);
// The sky's colour in a direction (what the cube map stores, before 8-bit rounding).
glm::vec3 skyRadiance(const glm::vec3& direction, const SkyOptions& options);
CubeFaces proceduralSky(const SkyOptions& options = {});

struct RippleOptions {
    int size = 64;   // texels per edge of one tileable frame
    int drops = 20;  // raindrop impacts per 16-frame cycle
    unsigned seed = 3;
};

// 16 tileable frames; each texel RGBA8: xyz the ripple normal (tangent space, z up)
// mapped to [0, 255], w the bump height. Drops start at random places and times in the
// cycle, and their rings widen and fade over a cycle, so frame 15 runs into frame 0.
struct RippleFrames {
    static constexpr int kFrames = 16;
    int size = 0;
    std::vector<std::uint8_t> rgba;  // frame-major: kFrames * size * size * 4
};
RippleFrames proceduralRipples(const RippleOptions& options = {});

// Frames per second of the ripple animation for a rain rate: 0 without rain, faster
// with heavier rain (RainCL §4.3.2: the frame rate follows the rain intensity).
double rippleFramesPerSecond(double rainMmPerHour);
// How strongly the ripples tilt the surface normal for a rain rate (0 without rain).
float rippleStrength(double rainMmPerHour);
// How many layers of the ripple map the surface shows, in [0, 4]: the rings per square
// metre grow with the rain (RainCL Table 2: drops per m^2 per s rise with the intensity).
// 0 without rain, 1 + log2(mm/h) / 2 clamped to [0.5, 4]: drizzle 0.5, light 1.0,
// moderate 2.0, heavy 3.0, cloudburst 4.
float rippleDensity(double rainMmPerHour);

}  // namespace prism::water
