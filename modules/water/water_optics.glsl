// Provides: the optics of the water surface: Schlick's Fresnel reflectance (F0 = 0.02
// for water), the capillary-ripple normal from the animated 16-frame normal-map array
// (RIPPLES variant only) and a Blinn highlight of the directional light.
#include <math_utils.glsl>

// Schlick: F = F0 + (1 - F0) (1 - cos)^5, cos clamped to [0, 1] (never pow of a negative).
float schlickFresnel(float f0, float cosTheta) {
    float m = 1.0 - clamp(cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * m2 * m2 * m;
}

float sunHighlight(vec3 n, vec3 toLight, vec3 toEye, float shininess) {
    vec3 h = safeNormalize(toLight + toEye, n);
    return safePow(max(dot(n, h), 0.0), shininess);
}

#if RIPPLES
uniform sampler2DArray u_ripples;
uniform float u_rippleFrame;     // frame position in [0, 16): integer part and blend
uniform float u_rippleScale;     // ripple-map repeats per metre
uniform float u_rippleStrength;  // 0..1: how far the ripple normal tilts the surface

// The surface normal `n` tilted by the ripple normal map at world position xz; the two
// frames around u_rippleFrame are blended so the animation has no visible steps.
vec3 rippleNormal(vec3 n, vec2 xz) {
    vec2 uv = xz * u_rippleScale;
    float f0 = floor(u_rippleFrame);
    float f1 = mod(f0 + 1.0, 16.0);
    float t = u_rippleFrame - f0;
    vec3 a = texture(u_ripples, vec3(uv, f0)).xyz * 2.0 - 1.0;
    vec3 b = texture(u_ripples, vec3(uv, f1)).xyz * 2.0 - 1.0;
    vec3 r = mix(a, b, t);
    // The map's normal is in a tangent frame with z up; the water's is y up.
    vec3 tilt = vec3(r.x, 0.0, r.y) * u_rippleStrength;
    return safeNormalize(n + tilt, n);
}
#endif
