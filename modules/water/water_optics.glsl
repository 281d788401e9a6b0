// Provides: the optics of the water surface: Schlick's Fresnel reflectance (F0 = 0.02
// for water), a normal turned towards the viewer (no back-facing ripple at grazing
// angles), the refraction of the view ray into shallow water, the capillary-ripple normal
// and bump from the animated 16-frame normal-map array (RIPPLES variant only) and a
// Blinn highlight of the directional light.
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

// The normal n (unit) with its component against the viewer removed down to
// dot(n, toEye) = minCos: a tilted ripple seen at a grazing angle would otherwise face
// away, reflect into the ground and flip between sky and ground from pixel to pixel
// (the "shards").
vec3 faceViewer(vec3 n, vec3 toEye, float minCos) {
    float c = dot(n, toEye);
    return c >= minCos ? n : safeNormalize(n + (minCos - c) * toEye, toEye);
}

// Where the view ray, refracted into water of this depth at the surface normal n, meets
// the ground: the horizontal offset in metres from the surface point (air -> water,
// index 1.333; a ray flatter than 1:4 is treated as 1:4 so grazing views stay local).
vec2 refractedGroundOffset(vec3 n, vec3 toEye, float depth) {
    vec3 r = refract(-toEye, n, 1.0 / 1.333);
    float down = max(-r.y, 0.25);
    return r.xz * (depth / down);
}

#if RIPPLES
uniform sampler2DArray u_ripples;
uniform float u_rippleFrame;     // frame position in [0, 16): integer part and blend
uniform float u_rippleScale;     // ripple-map repeats per metre
uniform float u_rippleStrength;  // 0..1: how far the ripple normal tilts the surface
uniform float u_rippleDensity;   // ripple layers in [0, 4]: more rain, more rings per m^2

// The surface normal `n` tilted by the ripples at world position xz, and the ripples'
// bump height (the map's alpha, 0..1) in `bump`. Up to four layers of the map, each at
// its own scale, offset and phase, fade in as u_rippleDensity grows, so the number of
// rings per square metre follows the rain intensity; the two frames around each layer's
// position are blended so the animation has no visible steps.
vec3 rippleNormal(vec3 n, vec2 xz, out float bump) {
    vec3 tilt = vec3(0.0);
    bump = 0.0;
    for (int k = 0; k < 4; ++k) {
        float weight = clamp(u_rippleDensity - float(k), 0.0, 1.0);
        if (weight <= 0.0) break;
        vec2 uv = xz * (u_rippleScale * (1.0 + 0.37 * float(k))) + vec2(0.31, 0.67) * float(k);
        float frame = mod(u_rippleFrame + 5.3 * float(k), 16.0);
        float f0 = floor(frame);
        float f1 = mod(f0 + 1.0, 16.0);
        vec4 r = mix(texture(u_ripples, vec3(uv, f0)), texture(u_ripples, vec3(uv, f1)), frame - f0);
        vec3 m = r.xyz * 2.0 - 1.0;
        // The map's normal is in a tangent frame with z up; the water's is y up.
        tilt += weight * vec3(m.x, 0.0, m.y);
        bump = max(bump, weight * r.w);
    }
    return safeNormalize(n + tilt * u_rippleStrength, n);
}
#endif
