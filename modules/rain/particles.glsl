// Provides: the rain particle (48 bytes, std430) and the two steps of the simulation,
// mirrored line by line on the CPU by prism/rain/rain_simulation.hpp:
//   rainSeedParticle(): a new drop in the camera's cylinder, placed in level-of-detail
//     rings (ring k of K holds a share falloff^k * (2k+1), area-uniform inside it);
//   rainStepParticle(): fall at the drop's terminal speed plus wind, then wrap: out of
//     the bottom -> respawn at the top from the seed (toroidal in height, relative to the
//     current cylinder); out of the side -> fold to the opposite side of the cylinder
//     (antipodal, so a fast camera move neither empties nor floods a region); further
//     than 3 radii away (a teleport) -> back to the seed column.
// Positions are world space; the cylinder is centred on u_cylinderCenter (the camera
// shifted vertically, see RainParams::below and groundHeight).
#include <rain/random.glsl>

struct RainParticle {
    vec4 seed;      // xyz: offset from the cylinder centre (the LOD placement); w: oscillation random
    vec4 position;  // xyz: world position; w: brightness random
    vec4 velocity;  // xyz: fall + sideways jitter, without wind (m/s); w: this drop's fall-speed factor
};

// Random channels of rainSeedParticle (the C++ reference uses the same numbers).
const uint RAIN_CH_RING = 0u;
const uint RAIN_CH_RADIUS = 1u;
const uint RAIN_CH_ANGLE = 2u;
const uint RAIN_CH_HEIGHT = 3u;
const uint RAIN_CH_SPEED = 4u;
const uint RAIN_CH_JITTER_X = 5u;
const uint RAIN_CH_JITTER_Z = 6u;
const uint RAIN_CH_OSCILLATION = 7u;
const uint RAIN_CH_BRIGHTNESS = 8u;
const float RAIN_TWO_PI = 6.28318530717958647692;

// Folds a horizontal offset back into the cylinder of radius R: unchanged inside;
// between R and 3R mirrored through the axis to radius 2R - r on the opposite side;
// further out (or not finite) the seed column.
vec2 rainFoldIntoCylinder(vec2 xz, vec2 seedXZ, float R) {
    float r = length(xz);
    if (r <= R) return xz;
    if (r < 3.0 * R) return xz * ((r - 2.0 * R) / r);
    return seedXZ;
}

// Horizontal offset of a drop at height y (relative to the centre) whose column passes
// through its seed at shearHeight (the eye's height relative to the centre): upwind
// above, downwind below, so that with wind the level-of-detail rings are centred on the
// camera at eye height, where the densest ring is seen.
vec2 rainWindShear(vec2 seedXZ, vec3 wind, float y, float shearHeight, float fallSpeed) {
    return seedXZ - wind.xz * ((y - shearHeight) / fallSpeed);
}

// cylinder = (radius, height); lod = (ring count K >= 1, density falloff per ring in (0, 1]).
RainParticle rainSeedParticle(uint index, uint seed, vec3 center, vec2 cylinder, vec2 lod, float fallSpeed,
                              float jitter, vec3 wind, float shearHeight) {
    float R = cylinder.x;
    float H = cylinder.y;
    int rings = int(lod.x);
    // Ring k has relative density falloff^k and relative area 2k + 1.
    float total = 0.0;
    float w = 1.0;
    for (int k = 0; k < rings; ++k) {
        total += w * float(2 * k + 1);
        w *= lod.y;
    }
    float pick = rainUniform(seed, index, RAIN_CH_RING) * total;
    int ring = rings - 1;
    float acc = 0.0;
    w = 1.0;
    for (int k = 0; k < rings; ++k) {
        acc += w * float(2 * k + 1);
        if (pick < acc) {
            ring = k;
            break;
        }
        w *= lod.y;
    }
    float fk = float(ring);
    float r = (R / float(rings)) * sqrt(fk * fk + rainUniform(seed, index, RAIN_CH_RADIUS) * (2.0 * fk + 1.0));
    r = min(r, R);
    float angle = RAIN_TWO_PI * rainUniform(seed, index, RAIN_CH_ANGLE);
    float y = (rainUniform(seed, index, RAIN_CH_HEIGHT) - 0.5) * H;
    float speedFactor = 0.9 + 0.2 * rainUniform(seed, index, RAIN_CH_SPEED);

    RainParticle p;
    p.seed = vec4(r * cos(angle), y, r * sin(angle), rainUniform(seed, index, RAIN_CH_OSCILLATION));
    float v = fallSpeed * speedFactor;
    p.velocity = vec4(jitter * (2.0 * rainUniform(seed, index, RAIN_CH_JITTER_X) - 1.0), -v,
                      jitter * (2.0 * rainUniform(seed, index, RAIN_CH_JITTER_Z) - 1.0), speedFactor);
    vec2 xz = rainFoldIntoCylinder(rainWindShear(p.seed.xz, wind, y, shearHeight, v), p.seed.xz, R);
    p.position = vec4(center + vec3(xz.x, y, xz.y), rainUniform(seed, index, RAIN_CH_BRIGHTNESS));
    return p;
}

// One step of dt seconds (dt already clamped by the caller) around the current centre.
RainParticle rainStepParticle(RainParticle p, vec3 center, float dt, vec3 wind, vec2 cylinder, float fallSpeed,
                              float shearHeight) {
    float R = cylinder.x;
    float H = cylinder.y;
    float halfH = 0.5 * H;
    vec3 pos = p.position.xyz + (p.velocity.xyz + wind) * dt;
    vec3 local = pos - center;
    if (local.y < -halfH) {
        // Out of the bottom: a new drop enters at the top (same phase, so the flux is
        // continuous), in its seed column, falling at the current intensity's speed.
        local.y -= H * floor((local.y + halfH) / H);
        float v = fallSpeed * p.velocity.w;
        p.velocity.y = -v;
        local.xz = rainWindShear(p.seed.xz, wind, local.y, shearHeight, v);
    } else if (local.y >= halfH) {
        // Out of the top (the camera moved down): wrap, keep the column.
        local.y -= H * floor((local.y + halfH) / H);
    }
    local.xz = rainFoldIntoCylinder(local.xz, p.seed.xz, R);
    p.position.xyz = center + local;
    return p;
}
