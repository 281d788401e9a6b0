// Provides: rainShadeStreak(uv), the colour of a streak fragment shared by all three
// drawing techniques: sky reflection (ambient x the bare streak shape) + sun + lamp,
// each light through the 4-layer blend of the streak texture array; premultiplied for
// glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA) (water drops mostly add light, so alpha
// is a fifth of the coverage); light brighter than 1 is scaled, not clipped, so a
// drop in the lamp's light keeps the lamp's hue. The FOG variant sends the colour
// through applyFog().
#include <rain/streak_lighting.glsl>
#include <rain/drop_lights.glsl>
#if FOG
#include <fog.glsl>
#endif

uniform vec3 u_ambient;

flat in vec4 s_bins;
flat in vec3 s_lampLight;
flat in float s_oscillation;
flat in float s_opacity;
in float s_eyeDistance;

vec4 rainShadeStreak(vec2 uv) {
    float shape = rainStreakShape(uv);
    float sun = rainStreakTexel(uv, s_bins.xy, s_oscillation);
    float lamp = rainStreakTexel(uv, s_bins.zw, s_oscillation);
    vec3 color = u_ambient * shape + u_sunColor * sun + s_lampLight * lamp;
#if FOG
    color = applyFog(color, s_eyeDistance);
#endif
    // A faint (far, thin) drop in the lamp's light still shows: its light may exceed 1
    // before the opacity; the result keeps the lamp's hue instead of clipping to white.
    vec3 light = color * s_opacity;
    light /= max(1.0, max(light.r, max(light.g, light.b)));
    float coverage = max(shape, max(sun, lamp));
    return vec4(light, 0.2 * coverage * s_opacity);
}
