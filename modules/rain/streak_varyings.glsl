// Provides: rainEmitStreakVaryings(), what every streak technique hands to the streak
// fragment stage per drop: streak-texture bins for the sun and the lamp, the lamp's
// light at the drop, the oscillation type and the opacity (see streak_geometry.glsl and
// streak_lighting.glsl). The caller declares the outputs s_bins, s_lampLight,
// s_oscillation, s_opacity and s_eyeDistance.
#include <rain/streak_geometry.glsl>
#include <rain/streak_lighting.glsl>
#include <rain/drop_lights.glsl>

struct RainDropShading {
    vec4 bins;        // sun theta/phi bins, lamp theta/phi bins
    vec3 lampLight;
    float oscillation;
};

RainDropShading rainDropShading(RainStreak s, vec4 seed) {
    RainDropShading d;
    vec3 toEye = safeNormalize(u_cameraPosition - s.head, vec3(0.0, 0.0, 1.0));
    vec3 toSun = safeNormalize(-u_sunDirection, vec3(0.0, 1.0, 0.0));
    vec3 toLamp = safeNormalize(u_lampPosition - s.head, vec3(0.0, 1.0, 0.0));
    d.bins = vec4(rainStreakBins(toSun, toEye, s.axisUp), rainStreakBins(toLamp, toEye, s.axisUp));
    d.lampLight = rainLampLight(s.head);
    d.oscillation = min(floor(seed.w * RAIN_OSCILLATION_TYPES), RAIN_OSCILLATION_TYPES - 1.0);
    return d;
}
