// Provides: the camera-facing streak quad of one rain particle (RainCL §4.1.3, Listing 3,
// after Tariq 2007): the quad runs from the drop's position back along its velocity
// (fall + wind) for the exposure time, so it is as long as fall speed x exposure and
// tilts with the wind; its width grows with distance (never below ~1.5 pixels, with the
// opacity scaled down by the same factor so thin far streaks keep their energy instead
// of aliasing). Also the per-drop opacity: 1/d^2-like falloff, fades at the cylinder's
// side and top, a few randomly brightened drops, and the level-of-detail weight: a drop of ring k,
// seeded at falloff^k of the centre's density, carries falloff^-k of a centre drop's light, so thinning
// far rain keeps the rain layer's expected light (rainLodWeight: w^(2/3) widens the streak, w^(1/3)
// raises its opacity). Shared by the geometry-shader,
// instanced and point-sprite techniques and the culling pass.
#include <transforms.glsl>
#include <math_utils.glsl>

uniform vec3 u_cameraPosition;
uniform vec3 u_cylinderCenter;
uniform vec2 u_cylinder;         // radius, height (m)
uniform vec3 u_wind;             // m/s
uniform float u_exposure;        // s: the streak is the drop's path during this time
uniform vec2 u_streakWidth;      // m: width = x + y * distance
uniform float u_viewportHeight;  // pixels
uniform float u_streakOpacity;   // opacity of a drop at distance 0
uniform float u_streakFalloff;   // m: opacity halves at this distance
uniform vec2 u_lod;              // level-of-detail rings K, density falloff per ring (as rain_init.comp)

struct RainStreak {
    vec3 head;      // the drop now
    vec3 tail;      // the drop one exposure time ago
    vec3 side;      // half the drawn width, across the streak, facing the camera
    vec3 axisUp;    // unit vector from head to tail (against the motion)
    float opacity;  // everything but the streak texture
    float eyeDistance;
};

// 1 / (relative density of the ring the drop was seeded in): falloff^-k for ring k = the seed's radius
// in units of R / K (rainSeedParticle places ring k's drops between k R / K and (k + 1) R / K).
float rainLodWeight(vec4 seed) {
    float rings = max(u_lod.x, 1.0);
    float ring = min(floor(length(seed.xz) * rings / u_cylinder.x), rings - 1.0);
    return pow(u_lod.y, -ring);
}

RainStreak rainStreak(vec4 seed, vec4 position, vec4 velocity) {
    RainStreak s;
    vec3 vel = velocity.xyz + u_wind;
    s.head = position.xyz;
    s.tail = s.head - vel * u_exposure;
    s.axisUp = safeNormalize(-vel, vec3(0.0, 1.0, 0.0));
    vec3 toEye = u_cameraPosition - s.head;
    float d = length(toEye);
    s.eyeDistance = d;
    vec3 across = cross(s.axisUp, toEye);
    if (dot(across, across) < 1e-8 * max(d * d, 1e-8)) across = cross(s.axisUp, vec3(1.0, 0.0, 0.0));
    if (dot(across, across) < 1e-12) across = vec3(0.0, 0.0, 1.0);
    across = normalize(across);

    float width = u_streakWidth.x + u_streakWidth.y * d;
    float pixel = 2.0 * d / (max(u_projection[1][1], 1e-6) * max(u_viewportHeight, 1.0));
    float drawn = max(width, 1.5 * pixel);
    // The level-of-detail weight w goes into the width (w^(2/3)) and the opacity (w^(1/3)), so the
    // streak's light grows by w without a thin far streak turning into a few over-bright pixels.
    float weight = rainLodWeight(seed);
    float widen = pow(weight, 2.0 / 3.0);
    s.side = across * (0.5 * drawn * widen);

    vec3 local = s.head - u_cylinderCenter;
    float radial = 1.0 - smoothstep(0.85 * u_cylinder.x, u_cylinder.x, length(local.xz));
    float top = 1.0 - smoothstep(0.4 * u_cylinder.y, 0.5 * u_cylinder.y, local.y);
    float falloff = 1.0 / (1.0 + (d * d) / (u_streakFalloff * u_streakFalloff));
    float bright = position.w > 0.96 ? 2.5 : 1.0;  // "a few drops randomly brightened"
    s.opacity = u_streakOpacity * (width / drawn) * falloff * radial * top * bright * (weight / widen);
    return s;
}

// Corners in triangle-strip order: 0 head-left, 1 head-right, 2 tail-left, 3 tail-right.
vec3 rainStreakCorner(RainStreak s, int corner) {
    vec3 base = (corner < 2) ? s.head : s.tail;
    return ((corner & 1) == 0) ? base - s.side : base + s.side;
}

// u across the streak (0..1), v along it from head (0) to tail (1).
vec2 rainStreakUv(int corner) {
    return vec2(float(corner & 1), float(corner >> 1));
}
