// rain_points: cuts the streak out of the point sprite: (across, along) coordinates of
// the fragment relative to the projected head-tail segment, then the shared streak colour.
#pragma prism variant FOG
#include <version.glsl>
#include <rain/streak_fragment.glsl>
#include <fragment_output.glsl>

flat in vec4 p_segment;
flat in float p_halfWidth;

void main() {
    vec2 a = p_segment.xy;
    vec2 ab = p_segment.zw - a;
    float len2 = dot(ab, ab);
    vec2 p = gl_PointCoord - a;
    float t = len2 > 1e-8 ? dot(p, ab) / len2 : 0.5;
    vec2 normal = len2 > 1e-8 ? vec2(-ab.y, ab.x) * inversesqrt(len2) : vec2(1.0, 0.0);
    float across = dot(p, normal) / max(2.0 * p_halfWidth, 1e-6) + 0.5;
    if (t < 0.0 || t > 1.0 || across < 0.0 || across > 1.0) discard;
    frag = rainShadeStreak(vec2(across, t));
    if (frag.a < 1.0 / 2048.0 && dot(frag.rgb, frag.rgb) < 1e-6) discard;
}
