// ground: wet paving (1 m tiles with dark joints and a random tone per tile) lit by the
// sun and the lamp (with falloff, modules/rain/drop_lights.glsl) plus a wet specular
// highlight, so the lamp's pool of light shows; u_emissive > 0 draws a light bulb in
// u_color instead. The FOG variant applies the distance fog.
#pragma prism variant FOG
#include <version.glsl>
#include <math_utils.glsl>
#include <rain/random.glsl>
#include <rain/drop_lights.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

uniform vec4 u_color;
uniform vec3 u_ambient;
uniform vec3 u_cameraPosition;
uniform float u_emissive;
uniform float u_shininess;
uniform float u_specular;

in vec3 v_worldPosition;
in vec3 v_worldNormal;

void main() {
    vec3 color;
    if (u_emissive > 0.0) {
        color = u_color.rgb * u_emissive;
    } else {
        vec3 n = safeNormalize(v_worldNormal, vec3(0.0, 1.0, 0.0));
        vec2 cell = floor(v_worldPosition.xz);
        vec2 f = v_worldPosition.xz - cell;
        float joint = smoothstep(0.0, 0.05, min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y)));
        ivec2 ic = ivec2(cell);
        uint h = pcgHash(uint(ic.x) * 73856093u ^ uint(ic.y) * 19349663u);
        float tone = 0.8 + 0.2 * float(h >> 8u) * (1.0 / 16777216.0);
        // Far away a tile is smaller than a pixel: fade the pattern to its average
        // instead of letting it alias into noise.
        float blur = clamp(4.0 * max(fwidth(v_worldPosition.x), fwidth(v_worldPosition.z)) - 0.4, 0.0, 1.0);
        joint = mix(joint, 0.85, blur);
        tone = mix(tone, 0.9, blur);
        vec3 albedo = u_color.rgb * tone * mix(0.4, 1.0, joint);

        vec3 toEye = safeNormalize(u_cameraPosition - v_worldPosition, n);
        vec3 toSun = safeNormalize(-u_sunDirection, vec3(0.0, 1.0, 0.0));
        vec3 toLamp = safeNormalize(u_lampPosition - v_worldPosition, vec3(0.0, 1.0, 0.0));
        vec3 lamp = rainLampLight(v_worldPosition);
        vec3 diffuse = max(dot(n, toSun), 0.0) * u_sunColor + max(dot(n, toLamp), 0.0) * lamp;
        float sunSpec = safePow(max(dot(n, safeNormalize(toSun + toEye, n)), 0.0), u_shininess);
        float lampSpec = safePow(max(dot(n, safeNormalize(toLamp + toEye, n)), 0.0), u_shininess);
        color = albedo * (u_ambient + diffuse) + u_specular * joint * (sunSpec * u_sunColor + lampSpec * lamp);
    }
#if FOG
    color = applyFog(color, length(u_cameraPosition - v_worldPosition));
#endif
    frag = vec4(color, 1.0);
}
