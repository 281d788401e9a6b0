// Checker: an unlit checkerboard from checker.glsl (no tint: this catalogue must not
// depend on tint.glsl).
#include <version.glsl>
#include <fragment_output.glsl>
#include <checker.glsl>

in vec2 v_uv;

void main() {
    frag = vec4(checker(v_uv), 1.0);
}
