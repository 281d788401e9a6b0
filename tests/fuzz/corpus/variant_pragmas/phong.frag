// Phong: diffuse and specular lighting per fragment from the interpolated normal;
// the BLINN variant uses the Blinn-Phong half vector instead of the reflection.
#pragma prism variant BLINN
#pragma prism variant FOG
#include <version.glsl>
#include <normals.glsl>
#include <lighting.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

in vec3 v_eyePosition;
in vec3 v_eyeNormal;

void main() {
    vec3 n = safeNormalize(v_eyeNormal, vec3(0.0, 0.0, 1.0));
    vec3 color = shade(v_eyePosition, n, true);
#if FOG
    color = applyFog(color, length(v_eyePosition));
#endif
    frag = vec4(color, 1.0);
}
