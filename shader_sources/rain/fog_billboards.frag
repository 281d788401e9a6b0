// fog_billboards: a soft disc of animated noise: two consecutive layers of the noise
// texture array (a loop through time) blended by u_time, scaled by u_fogStrength;
// premultiplied alpha. Soft particles against the ground: the disc fades out within
// u_fogSoftDistance above u_fogGroundHeight, so a billboard dipping into the ground
// leaves no hard line. The FOG variant also applies the distance fog.
#pragma prism variant FOG
#include <version.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

uniform sampler2DArray u_fogNoise;
uniform float u_fogStrength;
uniform float u_time;
uniform vec3 u_fogBillboardColor;
uniform float u_fogGroundHeight;
uniform float u_fogSoftDistance;

in vec2 f_uv;
flat in float f_random;
flat in float f_fade;
in float f_eyeDistance;
in float f_worldHeight;

void main() {
    float layers = float(textureSize(u_fogNoise, 0).z);
    float t = u_time * 0.8 + f_random * layers;
    float l0 = mod(floor(t), layers);
    float l1 = mod(l0 + 1.0, layers);
    vec2 uv = f_uv * 0.9 + vec2(f_random * 7.31, f_random * 3.17) + vec2(u_time * 0.004, 0.0);
    float n = mix(texture(u_fogNoise, vec3(uv, l0)).r, texture(u_fogNoise, vec3(uv, l1)).r, fract(t));
    float r = length(f_uv * 2.0 - 1.0);
    float disc = 1.0 - smoothstep(0.35, 1.0, r);
    float soft = smoothstep(0.0, u_fogSoftDistance, f_worldHeight - u_fogGroundHeight);
    float alpha = clamp(u_fogStrength * n * disc * f_fade * soft, 0.0, 1.0);
    if (alpha < 1.0 / 1024.0) discard;
    vec3 color = u_fogBillboardColor;
#if FOG
    color = applyFog(color, f_eyeDistance);
#endif
    frag = vec4(color * alpha, alpha);
}
