// Water surface (RainCL §4.3): the skybox reflected through reflect() on the (rippled)
// normal, mixed by Schlick's Fresnel term (F0 = u_fresnelF0, 0.02 for water) with a
// body colour whose opacity grows with depth, so shallow water looking down shows the
// terrain through it and grazing views mirror the sky. The directional light adds a
// Blinn highlight. The depth is taken per fragment (water level minus the bilinear
// terrain height), so the shore follows the terrain's contour line; output is
// premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA) and fades out at the shore between
// u_waterThreshold and u_shoreFadeDepth.
// RIPPLES (scenes with rain only): capillary ripples from the animated normal maps.
#pragma prism variant RIPPLES
#pragma prism variant FOG
#include <version.glsl>
#include <lights.glsl>
#include <water/water_optics.glsl>
#include <water/sky.glsl>
#include <fragment_output.glsl>

uniform vec3 u_cameraPosition;
uniform float u_waterThreshold;
uniform float u_shoreFadeDepth;
uniform float u_fresnelF0;
uniform vec3 u_waterTint;        // body colour of the water
uniform float u_waterAbsorption;  // 1/m: opacity = 1 - exp(-absorption x depth)
uniform sampler2D u_terrainHeight;  // R32F, linear filtering

in vec3 v_worldPosition;
in vec3 v_eyePosition;
in vec3 v_worldNormal;
in float v_surface;
in vec2 v_uv;

void main() {
    float depth = v_surface - texture(u_terrainHeight, v_uv).r;
    if (depth <= u_waterThreshold) discard;
    float shore = smoothstep(u_waterThreshold, u_shoreFadeDepth, depth);
    vec3 n = safeNormalize(v_worldNormal, vec3(0.0, 1.0, 0.0));
#if RIPPLES
    n = rippleNormal(n, v_worldPosition.xz);
#endif
    vec3 toEye = safeNormalize(u_cameraPosition - v_worldPosition, n);
    vec3 reflected = reflect(-toEye, n);
    reflected.y = abs(reflected.y);  // a ripple never mirrors the ground below the horizon
    vec3 sky = skyColor(reflected);
    float fresnel = schlickFresnel(u_fresnelF0, dot(n, toEye));
    float opacity = 1.0 - exp(-u_waterAbsorption * depth);

    vec3 light = u_ambient;
    vec3 highlight = vec3(0.0);
#if DIRECTIONAL_LIGHTS > 0
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        vec3 toLight = safeNormalize(-u_lightDirection[i], vec3(0.0, 1.0, 0.0));
        light += max(dot(n, toLight), 0.0) * u_lightColor[i];
        highlight += sunHighlight(n, toLight, toEye, 300.0) * u_lightColor[i];
    }
#endif
    vec3 color = fresnel * sky + (1.0 - fresnel) * opacity * u_waterTint * light + fresnel * 4.0 * highlight;
    float alpha = fresnel + (1.0 - fresnel) * opacity;
#if FOG
    // Fog the straight colour, then premultiply again.
    color = applyFog(color / alpha, length(v_eyePosition)) * alpha;
#endif
    frag = vec4(color, alpha) * shore;
}
