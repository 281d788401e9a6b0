// Provides: shade(), the full local lighting of one surface point in eye space:
// ambient + Lambert diffuse + specular (Phong, or Blinn-Phong when BLINN is 1) from
// every directional and point light, scaled by the material.
#include "lights.glsl"
#include "material.glsl"
#include "specular.glsl"

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
