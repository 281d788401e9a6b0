// Water surface (RainCL §4.3): Schlick's Fresnel (F0 = u_fresnelF0, 0.02 for water) mixes
// the reflected sky with the light coming up through the water: the ground under it,
// refracted (the view ray bent into the water meets the terrain at an offset that grows
// with the depth; the ground's albedo comes from u_terrainAlbedo, darkened as wet and
// lit like the terrain), dimmed by exp(-absorption x path) towards the body colour. So
// shallow puddles are clear and show the ground, grazing views mirror the bright sky,
// and deep water turns to the body colour. There is no draw threshold: the surface
// fades in with depth from 0 to u_shoreFadeDepth (premultiplied output, blend ONE,
// ONE_MINUS_SRC_ALPHA) and below that the terrain's own wet darkening shows the film.
// The normal is turned to face the viewer (no shards at grazing angles). The depth is the
// vertices' depth (level minus terrain) interpolated over the same triangles as the level
// and the terrain mesh, so it is zero exactly where the drawn surface meets the drawn
// terrain. Level minus the *bilinear* terrain disagreed with those triangles by up to a
// quarter of a cell's twist, which punched a hole into every cell of a thin film.
// RIPPLES (scenes with rain only): capillary ripples from the animated normal maps, as
// many layers as the rain's u_rippleDensity; their bump (crest height) adds reflection.
#pragma prism variant RIPPLES
#pragma prism variant FOG
#include <version.glsl>
#include <lights.glsl>
#include <water/water_optics.glsl>
#include <water/sky.glsl>
#include <fragment_output.glsl>

uniform vec3 u_cameraPosition;
uniform float u_shoreFadeDepth;
uniform float u_fresnelF0;
uniform vec3 u_waterTint;          // body colour of the water
uniform float u_waterAbsorption;   // 1/m: transmittance exp(-absorption x path)
uniform float u_wetDarkening;      // albedo factor of soaked ground
uniform float u_cellSize;
uniform sampler2D u_terrainAlbedo;  // RGBA8 albedo per cell, linear filtering

in vec3 v_worldPosition;
in vec3 v_eyePosition;
in vec3 v_worldNormal;
in float v_depth;  // water level minus terrain, per vertex
in vec2 v_uv;

void main() {
    float depth = v_depth;
    if (depth <= 0.0) discard;  // under the bank: the terrain is in front
    float shore = smoothstep(0.0, u_shoreFadeDepth, depth);
    vec3 up = vec3(0.0, 1.0, 0.0);
    vec3 toEye = safeNormalize(u_cameraPosition - v_worldPosition, up);
    vec3 n = safeNormalize(v_worldNormal, up);
    float bump = 0.0;
#if RIPPLES
    n = rippleNormal(n, v_worldPosition.xz, bump);
#endif
    n = faceViewer(n, toEye, 0.05);
    vec3 reflected = reflect(-toEye, n);
    reflected.y = abs(reflected.y);  // a ripple never mirrors the ground below the horizon
    vec3 sky = skyColor(reflected);
    float fresnel = clamp(schlickFresnel(u_fresnelF0, dot(n, toEye)) + 0.15 * bump, 0.0, 1.0);

    vec3 light = u_ambient;
    vec3 highlight = vec3(0.0);
#if DIRECTIONAL_LIGHTS > 0
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        vec3 toLight = safeNormalize(-u_lightDirection[i], up);
        light += max(dot(up, toLight), 0.0) * u_lightColor[i];
        highlight += sunHighlight(n, toLight, toEye, 300.0) * u_lightColor[i];
    }
#endif
    // The refracted ground, lit like the terrain (its normal taken as up) and wet.
    vec2 offset = refractedGroundOffset(n, toEye, depth);
    vec2 gridSize = vec2(textureSize(u_terrainAlbedo, 0));
    vec2 groundUv = v_uv + offset / (u_cellSize * gridSize);
    vec3 ground = texture(u_terrainAlbedo, groundUv).rgb * u_wetDarkening * light;
    vec3 r = refract(-toEye, n, 1.0 / 1.333);
    float path = depth / max(-r.y, 0.25);
    float transmittance = exp(-u_waterAbsorption * path);
    vec3 below = mix(u_waterTint * light, ground, transmittance);
    vec3 color = fresnel * sky + (1.0 - fresnel) * below + fresnel * 4.0 * highlight;
#if FOG
    color = applyFog(color, length(v_eyePosition));
#endif
    frag = vec4(color * shore, shore);
}
