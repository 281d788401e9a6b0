// rain_streaks: expands one particle into a camera-facing streak quad (two triangles
// of a strip, RainCL §4.1.3, Listing 3) along the drop's velocity; drops too faint to show
// (beyond the falloff, at the cylinder's edge) emit nothing.
#include <version.glsl>
#include <rain/streak_varyings.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no geometry stage: rain_instanced draws the same streaks there

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

in vec4 v_seed[];
in vec4 v_position[];
in vec4 v_velocity[];
out vec2 s_uv;
flat out vec4 s_bins;
flat out vec3 s_lampLight;
flat out float s_oscillation;
flat out float s_opacity;
out float s_eyeDistance;

void main() {
    RainStreak s = rainStreak(v_seed[0], v_position[0], v_velocity[0]);
    if (s.opacity < 1.0 / 512.0) return;
    RainDropShading d = rainDropShading(s, v_seed[0]);
    mat4 viewProjection = u_projection * u_view;
    for (int c = 0; c < 4; ++c) {
        s_uv = rainStreakUv(c);
        s_bins = d.bins;
        s_lampLight = d.lampLight;
        s_oscillation = d.oscillation;
        s_opacity = s.opacity;
        s_eyeDistance = s.eyeDistance;
        gl_Position = viewProjection * vec4(rainStreakCorner(s, c), 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
