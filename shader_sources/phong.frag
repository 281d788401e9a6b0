// Phong: diffuse and specular lighting per fragment from the interpolated normal;
// the BLINN variant uses the Blinn-Phong half vector instead of the reflection.
#pragma prism variant BLINN
#include <version.glsl>
#include <normals.glsl>
#include <lighting.glsl>
#include <fragment_output.glsl>

in vec3 v_eyePosition;
in vec3 v_eyeNormal;

void main() {
    vec3 n = safeNormalize(v_eyeNormal, vec3(0.0, 0.0, 1.0));
    frag = vec4(shade(v_eyePosition, n, true), 1.0);
}
