#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp samplerCube;
precision highp sampler3D;
precision highp samplerCubeShadow;
precision highp sampler2DShadow;
precision highp sampler2DArray;
precision highp sampler2DArrayShadow;
precision highp isampler2D;
precision highp isampler3D;
precision highp isamplerCube;
precision highp isampler2DArray;
precision highp usampler2D;
precision highp usampler3D;
precision highp usamplerCube;
precision highp usampler2DArray;
#define BLINN 1
#define FOG 1
#define DIRECTIONAL_LIGHTS 1
#define POINT_LIGHTS 1
#line 1 0
// Phong: diffuse and specular lighting per fragment from the interpolated normal;
// the BLINN variant uses the Blinn-Phong half vector instead of the reflection.


#line 1 1
// Provides: the GLSL version every Prism shader targets (330 core) and default precision.

precision highp float;
#line 6 0
#line 1 2
// Provides: eyeNormal(), the object-space normal in eye space through u_normal,
// normalised safely (a zero or degenerate normal becomes the view axis, never NaN).
#line 1 3
// Provides: numerically safe helpers: safeNormalize (never normalises a zero or
// non-finite vector) and safePow (defined for a zero base and any exponent).


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
#line 4 2
#line 1 4
// Provides: the engine's transform uniforms (u_world, u_view, u_projection, u_normal)
// and helpers from object space to world, eye and clip space. u_normal is the
// inverse-transpose of the upper 3x3 of u_view * u_world (eye-space normals).
uniform mat4 u_world;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform mat3 u_normal;

vec4 eyePosition(vec3 objectPosition) {
    return u_view * (u_world * vec4(objectPosition, 1.0));
}

vec4 clipPosition(vec4 eye) {
    return u_projection * eye;
}
#line 5 2

vec3 eyeNormal(vec3 objectNormal) {
    return safeNormalize(u_normal * objectNormal, vec3(0.0, 0.0, 1.0));
}
#line 7 0
#line 1 5
// Provides: shade(), the full local lighting of one surface point in eye space:
// ambient + Lambert diffuse + specular (Phong, or Blinn-Phong when BLINN is 1) from
// every directional and point light, scaled by the material.
#line 1 6
// Provides: ambient light plus DIRECTIONAL_LIGHTS directional and POINT_LIGHTS point
// lights, with their directions in eye space. Both counts are
// variant axes: a scene's draws use the variant whose arrays just hold its lights, so
// light loops are bounded by the scene (and a scene without point lights has no point
// light code). u_*Count says how many entries are in use. Directions point from the
// light into the scene, in world space. Composed programs get 4 and 1 by default.





#ifndef DIRECTIONAL_LIGHTS
#define DIRECTIONAL_LIGHTS 4
#endif
#ifndef POINT_LIGHTS
#define POINT_LIGHTS 1
#endif

uniform vec3 u_ambient;
#if DIRECTIONAL_LIGHTS > 0
uniform int u_directionalLightCount;
uniform vec3 u_lightDirection[DIRECTIONAL_LIGHTS];
uniform vec3 u_lightColor[DIRECTIONAL_LIGHTS];

// Unit vector from the surface towards directional light i, in eye space.
vec3 directionToLight(int i) {
    return safeNormalize(mat3(u_view) * -u_lightDirection[i], vec3(0.0, 0.0, 1.0));
}
#endif
#if POINT_LIGHTS > 0
uniform int u_pointLightCount;
uniform vec3 u_pointLightPosition[POINT_LIGHTS];
uniform vec3 u_pointLightColor[POINT_LIGHTS];
#endif
#line 5 5
#line 1 7
// Provides: the material uniforms: base colour, shininess (Phong exponent) and
// specular strength.
uniform vec4 u_color;
uniform float u_shininess;
uniform float u_specular;
#line 6 5
#line 1 8
// Provides: specular highlight terms, Phong (reflected light vs view) and Blinn-Phong
// (half vector vs normal). Nothing is added to the highlight, and pow(0, 0) is never
// evaluated (docs/references.md: the bugs of the shaders Prism replaced).


float phongSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 r = reflect(-toLight, normal);
    return safePow(max(dot(r, toEye), 0.0), shininess);
}

float blinnSpecular(vec3 toLight, vec3 toEye, vec3 normal, float shininess) {
    vec3 h = safeNormalize(toLight + toEye, normal);
    return safePow(max(dot(h, normal), 0.0), shininess);
}
#line 7 5

#ifndef BLINN
#define BLINN 0
#endif

vec3 specularTerm(vec3 toLight, vec3 toEye, vec3 normal) {
#if BLINN
    return vec3(blinnSpecular(toLight, toEye, normal, u_shininess));
#else
    return vec3(phongSpecular(toLight, toEye, normal, u_shininess));
#endif
}

vec3 lightContribution(vec3 toLight, vec3 radiance, vec3 toEye, vec3 normal, bool withSpecular) {
    float lambert = dot(normal, toLight);
    if (lambert <= 0.0) return vec3(0.0);
    vec3 c = u_color.rgb * lambert;
    if (withSpecular) c += u_specular * specularTerm(toLight, toEye, normal);
    return c * radiance;
}

// `eyePos` is the surface point, `normal` its unit normal, both in eye space.
vec3 shade(vec3 eyePos, vec3 normal, bool withSpecular) {
    vec3 toEye = safeNormalize(-eyePos, vec3(0.0, 0.0, 1.0));
    vec3 color = u_ambient * u_color.rgb;
#if DIRECTIONAL_LIGHTS > 0
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        color += lightContribution(directionToLight(i), u_lightColor[i], toEye, normal, withSpecular);
    }
#endif
#if POINT_LIGHTS > 0
    for (int i = 0; i < POINT_LIGHTS; ++i) {
        if (i >= u_pointLightCount) break;
        vec3 lightEye = (u_view * vec4(u_pointLightPosition[i], 1.0)).xyz;
        vec3 toLight = safeNormalize(lightEye - eyePos, normal);
        color += lightContribution(toLight, u_pointLightColor[i], toEye, normal, withSpecular);
    }
#endif
    return color;
}
#line 8 0
#line 1 9
// Provides: the single colour output of a fragment stage, `frag`.
out vec4 frag;
#line 9 0
#if FOG
#line 1 10
// Provides: exponential distance fog, applyFog(colour, eyeDistance) = mix(u_fogColor,
// colour, exp(-u_fogDensity * distance)). Shaders include it only under `#if FOG`
// (the FOG variant), so a scene without fog runs no fog code and has no fog uniforms.
uniform vec3 u_fogColor;
uniform float u_fogDensity;

// Never NaN for density >= 0 and finite distances: the exponent is clamped.
vec3 applyFog(vec3 color, float eyeDistance) {
    float visibility = exp(-clamp(u_fogDensity * max(eyeDistance, 0.0), 0.0, 80.0));
    return mix(u_fogColor, color, visibility);
}
#line 11 0
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
