// Terrain: Lambert lighting of the vertex albedo by the directional lights (world
// space) plus ambient. WET (scenes with water only): ground under water or wet from it
// is darkened smoothly, 1 - exp(-depth / u_wetFilmDepth) of the way to u_wetDarkening,
// so even a film far thinner than a millimetre shows as damp ground (no threshold).
// FOG: exponential distance fog (modules/fog.glsl).
#pragma prism variant WET
#pragma prism variant FOG
#include <version.glsl>
#include <lights.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif
#if WET
uniform sampler2D u_waterDepth;  // RG32F: compensated water depth (hi, lo) per cell
uniform float u_wetDarkening;    // albedo factor of soaked ground
uniform float u_wetFilmDepth;    // m: a film this deep darkens 63 % of the way
#endif

in vec3 v_worldNormal;
in vec3 v_eyePosition;
in vec3 v_albedo;
in vec2 v_uv;

void main() {
    vec3 n = safeNormalize(v_worldNormal, vec3(0.0, 1.0, 0.0));
    vec3 albedo = v_albedo;
#if WET
    vec2 w = texture(u_waterDepth, v_uv).rg;
    float wet = 1.0 - exp(-max(w.x + w.y, 0.0) / u_wetFilmDepth);
    albedo *= mix(1.0, u_wetDarkening, wet);
#endif
    vec3 color = u_ambient * albedo;
#if DIRECTIONAL_LIGHTS > 0
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        vec3 toLight = safeNormalize(-u_lightDirection[i], vec3(0.0, 1.0, 0.0));
        color += max(dot(n, toLight), 0.0) * u_lightColor[i] * albedo;
    }
#endif
#if FOG
    color = applyFog(color, length(v_eyePosition));
#endif
    frag = vec4(color, 1.0);
}
