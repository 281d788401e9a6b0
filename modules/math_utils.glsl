// Provides: numerically safe helpers: safeNormalize (never normalises a zero or
// non-finite vector) and safePow (defined for a zero base and any exponent).
#pragma once

const float PRISM_EPSILON = 1e-20;

// normalize(v), or `fallback` when v is (nearly) zero; `normalize` of a zero vector is undefined.
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float len2 = dot(v, v);
    return (len2 > PRISM_EPSILON && len2 < 3.0e38) ? v * inversesqrt(len2) : fallback;
}

// pow(x, y) for x >= 0 that is 0 for x == 0 (GLSL's pow is undefined for x == 0, y <= 0)
// and never NaN; y is clamped to >= 1e-6 so pow(0, 0) is never evaluated.
float safePow(float x, float y) {
    float e = max(y, 1e-6);
    return x > 0.0 ? exp2(e * log2(x)) : 0.0;
}
