// rain_instanced: the instanced technique. glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0,
// 4, count): every instance is one particle (attributes with divisor 1, read from the
// simulation buffer) and gl_VertexID picks the quad corner; the same quad as rain_streaks.
#include <version.glsl>
#include <rain/streak_varyings.glsl>

in vec4 a_rainSeed;
in vec4 a_rainPosition;
in vec4 a_rainVelocity;
out vec2 s_uv;
flat out vec4 s_bins;
flat out vec3 s_lampLight;
flat out float s_oscillation;
flat out float s_opacity;
out float s_eyeDistance;

void main() {
    RainStreak s = rainStreak(a_rainSeed, a_rainPosition, a_rainVelocity);
    RainDropShading d = rainDropShading(s, a_rainSeed);
    int corner = gl_VertexID & 3;
    s_uv = rainStreakUv(corner);
    s_bins = d.bins;
    s_lampLight = d.lampLight;
    s_oscillation = d.oscillation;
    s_opacity = s.opacity;
    s_eyeDistance = s.eyeDistance;
    // A faint drop becomes a degenerate quad outside the clip volume (culled).
    gl_Position = s.opacity < 1.0 / 512.0 ? vec4(2.0, 2.0, 2.0, 1.0)
                                           : u_projection * u_view * vec4(rainStreakCorner(s, corner), 1.0);
}
