// Provides: the fragment stage of the quad streak techniques (geometry shader and
// instanced): sky reflection + sun + lamp, each light through the 4-layer blend of the
// streak texture array; premultiplied output for glBlendFunc(GL_ONE,
// GL_ONE_MINUS_SRC_ALPHA); the FOG variant sends the colour through applyFog().
#include <rain/streak_lighting.glsl>
#include <rain/drop_lights.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

uniform vec3 u_ambient;

in vec2 s_uv;
flat in vec4 s_bins;
flat in vec3 s_lampLight;
flat in float s_oscillation;
flat in float s_opacity;
in float s_eyeDistance;

void main() {
    float shape = rainStreakShape(s_uv);
    float sun = rainStreakTexel(s_uv, s_bins.xy, s_oscillation);
    float lamp = rainStreakTexel(s_uv, s_bins.zw, s_oscillation);
    vec3 color = u_ambient * shape + u_sunColor * sun + s_lampLight * lamp;
#if FOG
    color = applyFog(color, s_eyeDistance);
#endif
    float coverage = max(shape, max(sun, lamp));
    if (coverage * s_opacity < 1.0 / 512.0) discard;
    frag = vec4(color * s_opacity, 0.2 * coverage * s_opacity);
}
