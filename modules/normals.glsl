// Provides: eyeNormal(), the object-space normal in eye space through u_normal,
// normalised safely (a zero or degenerate normal becomes the view axis, never NaN).
#include "math_utils.glsl"
#include "transforms.glsl"

vec3 eyeNormal(vec3 objectNormal) {
    return safeNormalize(u_normal * objectNormal, vec3(0.0, 0.0, 1.0));
}
