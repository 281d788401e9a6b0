// rain_streaks: the streak's light- and view-dependent colour (modules/rain/streak_fragment.glsl).
#pragma prism variant FOG
#include <version.glsl>
#include <rain/streak_fragment.glsl>
#include <fragment_output.glsl>

in vec2 s_uv;

void main() {
    frag = rainShadeStreak(s_uv);
    if (frag.a < 1.0 / 2048.0 && dot(frag.rgb, frag.rgb) < 1e-6) discard;
}
