// Provides: specular highlight terms, Phong (reflected light vs view) and Blinn-Phong
// (half vector vs normal). Nothing is added to the highlight, and pow(0, 0) is never
// evaluated (docs/references.md: the bugs of the shaders Prism replaced).
#include "math_utils.glsl"

float phongSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 r = reflect(-toLight, normal);
    return safePow(max(dot(r, toEye), 0.0), shininess);
}

float blinnSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 h = safeNormalize(toLight + toEye, normal);
    return safePow(max(dot(h, normal), 0.0), shininess);
}
