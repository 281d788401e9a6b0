// Tinted Phong: Prism's per-fragment Phong lighting (Blinn-Phong in the BLINN
// variant), then the consumer's tint from tint.glsl.
#pragma prism variant BLINN
#include <version.glsl>
#include <lighting.glsl>
#include <fragment_output.glsl>
#include <tint.glsl>

in vec3 v_eyePosition;
in vec3 v_eyeNormal;

void main() {
    vec3 n = safeNormalize(v_eyeNormal, vec3(0.0, 0.0, 1.0));
    frag = vec4(applyTint(shade(v_eyePosition, n, true)), 1.0);
}
