// rain_points: the point-sprite technique. One GL_POINTS vertex per particle with
// gl_PointSize covering the projected streak (at most 255 pixels); the fragment stage
// cuts the streak out of the square with gl_PointCoord. Cheapest, but long streaks
// close to the camera are cut at the sprite's size.
#include <version.glsl>
#include <rain/streak_varyings.glsl>

in vec4 a_rainSeed;
in vec4 a_rainPosition;
in vec4 a_rainVelocity;
flat out vec4 p_segment;     // head.xy, tail.xy in gl_PointCoord units (y down)
flat out float p_halfWidth;  // in gl_PointCoord units
flat out vec4 s_bins;
flat out vec3 s_lampLight;
flat out float s_oscillation;
flat out float s_opacity;
out float s_eyeDistance;

void main() {
    RainStreak s = rainStreak(a_rainSeed, a_rainPosition, a_rainVelocity);
    RainDropShading d = rainDropShading(s, a_rainSeed);
    s_bins = d.bins;
    s_lampLight = d.lampLight;
    s_oscillation = d.oscillation;
    s_opacity = s.opacity;
    s_eyeDistance = s.eyeDistance;
    p_segment = vec4(0.5);
    p_halfWidth = 0.0;

    mat4 viewProjection = u_projection * u_view;
    vec4 headClip = viewProjection * vec4(s.head, 1.0);
    vec4 tailClip = viewProjection * vec4(s.tail, 1.0);
    float minW = 1e-3;
    if (s.opacity < 1.0 / 512.0 || headClip.w < minW || tailClip.w < minW) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // culled
        gl_PointSize = 1.0;
        return;
    }
    float viewportWidth = u_viewportHeight * u_projection[1][1] / max(u_projection[0][0], 1e-6);
    vec2 viewport = vec2(viewportWidth, u_viewportHeight);
    vec2 headPx = (headClip.xy / headClip.w * 0.5 + 0.5) * viewport;
    vec2 tailPx = (tailClip.xy / tailClip.w * 0.5 + 0.5) * viewport;
    float metresPerPixel = 2.0 * s.eyeDistance / (max(u_projection[1][1], 1e-6) * max(u_viewportHeight, 1.0));
    float widthPx = 2.0 * length(s.side) / max(metresPerPixel, 1e-9);
    float size = min(max(length(headPx - tailPx), widthPx) + 2.0, 255.0);
    vec2 centerPx = 0.5 * (headPx + tailPx);
    p_segment = vec4(0.5 + (headPx.x - centerPx.x) / size, 0.5 - (headPx.y - centerPx.y) / size,
                     0.5 + (tailPx.x - centerPx.x) / size, 0.5 - (tailPx.y - centerPx.y) / size);
    p_halfWidth = 0.5 * widthPx / size;
    gl_PointSize = size;
    gl_Position = vec4(centerPx / viewport * 2.0 - 1.0, headClip.z / headClip.w, 1.0);
}
