// Diffraction material: ambient plus, for every directional and point light of the scene
// (lights.glsl's variant axes), Stam's diffraction BRDF (modules/diffraction/stam.glsl)
// times the light's colour and cos(theta_i), in the tangent frame of the interpolated normal
// and u_diffractionTangent. The FOG variant adds the scene's distance fog, as the classic
// shaders do.
#pragma prism variant FOG
#include <version.glsl>
#include <lights.glsl>
#include <material.glsl>
#include <diffraction/stam.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

in vec3 v_eyePosition;
in vec3 v_eyeNormal;
in vec3 v_eyeTangent;

vec3 diffractionLight(vec3 toLight, vec3 radiance, mat3 toTangent, vec3 toViewerT) {
    vec3 toLightT = toTangent * toLight;
    return diffractionRgb(toLightT, toViewerT) * radiance * max(toLightT.z, 0.0);
}

void main() {
    vec3 n = safeNormalize(v_eyeNormal, vec3(0.0, 0.0, 1.0));
    vec3 fallback = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t = safeNormalize(v_eyeTangent - n * dot(n, v_eyeTangent), safeNormalize(cross(fallback, n), fallback));
    vec3 b = cross(n, t);
    mat3 toTangent = transpose(mat3(t, b, n));
    vec3 toViewerT = toTangent * safeNormalize(-v_eyePosition, n);
    vec3 color = u_ambient * u_color.rgb;
#if DIRECTIONAL_LIGHTS > 0
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        color += diffractionLight(directionToLight(i), u_lightColor[i], toTangent, toViewerT);
    }
#endif
#if POINT_LIGHTS > 0
    for (int i = 0; i < POINT_LIGHTS; ++i) {
        if (i >= u_pointLightCount) break;
        vec3 lightEye = (u_view * vec4(u_pointLightPosition[i], 1.0)).xyz;
        color += diffractionLight(safeNormalize(lightEye - v_eyePosition, n), u_pointLightColor[i], toTangent, toViewerT);
    }
#endif
#if FOG
    color = applyFog(color, length(v_eyePosition));
#endif
    frag = vec4(color, 1.0);
}
