// Provides: ambient light plus up to PRISM_DIRECTIONAL_LIGHTS directional lights and
// PRISM_POINT_LIGHTS point lights (as in the FUDGE seed), with their directions in
// eye space. Directions point from the light into the scene, in world space.
#include "math_utils.glsl"
#include "transforms.glsl"

#ifndef PRISM_DIRECTIONAL_LIGHTS
#define PRISM_DIRECTIONAL_LIGHTS 4
#endif
#ifndef PRISM_POINT_LIGHTS
#define PRISM_POINT_LIGHTS 1
#endif

uniform vec3 u_ambient;
uniform int u_directionalLightCount;
uniform vec3 u_lightDirection[PRISM_DIRECTIONAL_LIGHTS];
uniform vec3 u_lightColor[PRISM_DIRECTIONAL_LIGHTS];
#if PRISM_POINT_LIGHTS > 0
uniform int u_pointLightCount;
uniform vec3 u_pointLightPosition[PRISM_POINT_LIGHTS];
uniform vec3 u_pointLightColor[PRISM_POINT_LIGHTS];
#endif

// Unit vector from the surface towards directional light i, in eye space.
vec3 directionToLight(int i) {
    return safeNormalize(mat3(u_view) * -u_lightDirection[i], vec3(0.0, 0.0, 1.0));
}
