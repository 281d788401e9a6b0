// Provides: specular highlight terms, Phong (reflected light vs view) and Blinn-Phong
// (half vector vs normal), without the seed's constant added to the highlight and
// without evaluating pow(0, 0).
#include "math_utils.glsl"

float phongSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 r = reflect(-toLight, normal);
    return safePow(max(dot(r, toEye), 0.0), shininess);
}

float blinnSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 h = safeNormalize(toLight + toEye, normal);
    return safePow(max(dot(h, normal), 0.0), shininess);
}
