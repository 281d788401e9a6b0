// Provides: diffractionRgb(toLight, toViewer), Stam's diffraction BRDF (relative to a flat
// mirror's specular peak) as linear sRGB under D65, from the lookup tables that
// prism_diffraction_core builds (runtime/diffraction, lookup_tables.hpp; docs/diffraction.md).
// Both directions are unit vectors in the surface's tangent frame (z = normal, x = across the
// grooves). DIFFRACTION_PATH picks the path:
//   0 (a): per wavelength, P = sum_n (i k w s)^n / n! H_n(u / lambda, v / lambda) from the RG
//          layers 0..N of u_diffractionTables, |P|^2 weighted by u_diffractionWavelengths;
//   1 (b): sum_t w^t T_t(u, v) from the RGB layers 0..2N (pre-integrated over wavelength);
//   2 (c): path b's sum tabulated at u_diffractionSlices values of w: one trilinear fetch
//          from u_diffractionVolume.
// N (u_diffractionTerms) and the wavelengths (u_diffractionWavelengthCount) are uniforms.
#pragma prism variant DIFFRACTION_PATH 0 1 2
#include <math_utils.glsl>

#ifndef DIFFRACTION_PATH
#define DIFFRACTION_PATH 0
#endif

uniform float u_diffractionTableSize;        // S texels per side
uniform float u_diffractionExtent;           // table covers [-extent, extent]^2
#if DIFFRACTION_PATH == 2
uniform sampler3D u_diffractionVolume;       // linear filtering, clamp to edge
uniform float u_diffractionSlices;           // K slices of w in [-2, 0]
#else
uniform sampler2DArray u_diffractionTables;  // linear filtering, clamp to edge
uniform int u_diffractionTerms;              // N
#endif
#if DIFFRACTION_PATH == 0
uniform float u_diffractionHeightScale;      // s = max |h| in nm
uniform sampler2D u_diffractionWavelengths;  // 1 row: rgb = weight, a = wavelength in nm
uniform int u_diffractionWavelengthCount;
#endif

// Texture coordinate of a table point: texel i is centred at (i - S/2) * 2 extent / S.
vec2 diffractionTexcoord(vec2 p) {
    float cell = 2.0 * u_diffractionExtent / u_diffractionTableSize;
    return (p / cell + 0.5 * u_diffractionTableSize + 0.5) / u_diffractionTableSize;
}

vec3 diffractionRgb(vec3 toLight, vec3 toViewer) {
    if (toLight.z <= 1e-6 || toViewer.z <= 1e-6) return vec3(0.0);  // below the horizon
    vec3 uvw = -toLight - toViewer;                                  // w <= -2e-6 here
    float ratio = (1.0 + dot(toLight, toViewer)) / uvw.z;
    float geometry = ratio * ratio / (toLight.z * toViewer.z);      // G / w^2
    vec3 sum = vec3(0.0);
#if DIFFRACTION_PATH == 2
    float slice = clamp((uvw.z + 2.0) * 0.5 * (u_diffractionSlices - 1.0), 0.0, u_diffractionSlices - 1.0);
    sum = texture(u_diffractionVolume, vec3(diffractionTexcoord(uvw.xy), (slice + 0.5) / u_diffractionSlices)).rgb;
#elif DIFFRACTION_PATH == 1
    vec2 tc = diffractionTexcoord(uvw.xy);
    float wPower = 1.0;
    for (int t = 0; t <= 2 * u_diffractionTerms; ++t) {
        sum += wPower * texture(u_diffractionTables, vec3(tc, float(t))).rgb;
        wPower *= uvw.z;
    }
#else
    for (int i = 0; i < u_diffractionWavelengthCount; ++i) {
        vec4 wavelength = texelFetch(u_diffractionWavelengths, ivec2(i, 0), 0);
        float a = 6.283185307179586 / wavelength.a * uvw.z * u_diffractionHeightScale;
        vec2 tc = diffractionTexcoord(uvw.xy / wavelength.a);
        vec2 factor = vec2(1.0, 0.0);  // (i a)^n / n!
        vec2 p = vec2(0.0);
        for (int n = 0; n <= u_diffractionTerms; ++n) {
            if (n > 0) factor = vec2(-factor.y, factor.x) * (a / float(n));
            vec2 h = texture(u_diffractionTables, vec3(tc, float(n))).rg;
            p += vec2(factor.x * h.x - factor.y * h.y, factor.x * h.y + factor.y * h.x);
        }
        sum += dot(p, p) * wavelength.rgb;
    }
#endif
    return geometry * sum;
}
