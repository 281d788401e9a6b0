// soft_shadows: the soft-shadow demo of prism/bluenoise/soft_shadows.hpp on the GPU: the
// ground under a strip light, seen from straight above, shadowed by up to 3 spheres;
// u_spp light samples per pixel from prismBlueNoiseSample (white, blue noise or sorted,
// modules/bluenoise/sampling.glsl), frame u_frame. Writes the irradiance relative to the
// unoccluded irradiance below the light (u_light.w scales it), unclamped, to frag.r.
#include <version.glsl>
#include <bluenoise/sampling.glsl>
#include <fragment_output.glsl>

uniform uint u_frame;
uniform int u_spp;
uniform vec2 u_imageSize;
uniform float u_extent;
uniform vec4 u_light;  // height, half-length (x), half-width (y), scale
uniform vec4 u_sphere0;  // xyz centre, w radius (radius 0: none)
uniform vec4 u_sphere1;
uniform vec4 u_sphere2;

bool hitsSphere(vec3 o, vec3 d, vec4 s) {
    if (s.w <= 0.0) return false;
    vec3 oc = o - s.xyz;
    float a = dot(d, d), b = 2.0 * dot(oc, d), c = dot(oc, oc) - s.w * s.w;
    float disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return false;
    float root = sqrt(disc);
    float t0 = (-b - root) / (2.0 * a), t1 = (-b + root) / (2.0 * a);
    return (t0 > 0.0 && t0 < 1.0) || (t1 > 0.0 && t1 < 1.0);
}

void main() {
    // Row 0 at the top, as on the CPU.
    uvec2 pixel = uvec2(uint(gl_FragCoord.x), uint(u_imageSize.y - gl_FragCoord.y));
    vec2 ground = vec2((float(pixel.x) + 0.5) / u_imageSize.x * 2.0 * u_extent - u_extent,
                       u_extent - (float(pixel.y) + 0.5) / u_imageSize.y * 2.0 * u_extent);
    float area = 4.0 * u_light.y * u_light.z;
    float sum = 0.0;
    for (int i = 0; i < u_spp; ++i) {
        uint index = u_frame * uint(u_spp) + uint(i);
        float u = prismBlueNoiseSample(pixel, index, 0u), v = prismBlueNoiseSample(pixel, index, 1u);
        vec3 q = vec3((2.0 * u - 1.0) * u_light.y, (2.0 * v - 1.0) * u_light.z, u_light.x);
        vec3 p = vec3(ground, 0.0);
        vec3 d = q - p;
        float r2 = dot(d, d);
        bool blocked = hitsSphere(p, d, u_sphere0) || hitsSphere(p, d, u_sphere1) || hitsSphere(p, d, u_sphere2);
        sum += blocked ? 0.0 : area * (u_light.x * u_light.x / r2) / r2;
    }
    frag = vec4(u_light.w * sum / float(u_spp), 0.0, 0.0, 1.0);
}
