// Provides: ambient light plus DIRECTIONAL_LIGHTS directional and POINT_LIGHTS point
// lights, with their directions in eye space. Both counts are
// variant axes: a scene's draws use the variant whose arrays just hold its lights, so
// light loops are bounded by the scene (and a scene without point lights has no point
// light code). u_*Count says how many entries are in use. Directions point from the
// light into the scene, in world space. Composed programs get 4 and 1 by default.
#pragma prism variant DIRECTIONAL_LIGHTS 0 1 2 4 8
#pragma prism variant POINT_LIGHTS 0 1 4
#include "math_utils.glsl"
#include "transforms.glsl"

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
