// fog_billboards: one screen-aligned square of u_fogBillboardSize metres per billboard,
// faded out as the camera comes close so a sprite never fills the screen abruptly.
#include <version.glsl>
#include <transforms.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no geometry stage

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec3 u_cameraPosition;
uniform float u_fogBillboardSize;

in vec4 v_billboard[];
out vec2 f_uv;
flat out float f_random;
flat out float f_fade;
out float f_eyeDistance;
out float f_worldHeight;  // world y of the fragment (soft fade against the ground)

void main() {
    vec3 center = v_billboard[0].xyz;
    float d = length(u_cameraPosition - center);
    float size = u_fogBillboardSize;
    float fade = smoothstep(0.25 * size, 0.75 * size, d);
    if (fade <= 0.0) return;
    // The camera's right and up axes in world space: rows of the view matrix.
    vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]) * (0.5 * size);
    vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]) * (0.5 * size);
    mat4 viewProjection = u_projection * u_view;
    for (int c = 0; c < 4; ++c) {
        vec2 corner = vec2(float(c & 1), float(c >> 1));
        vec3 p = center + right * (2.0 * corner.x - 1.0) + up * (2.0 * corner.y - 1.0);
        f_uv = corner;
        f_random = v_billboard[0].w;
        f_fade = fade;
        f_eyeDistance = length(u_cameraPosition - p);
        f_worldHeight = p.y;
        gl_Position = viewProjection * vec4(p, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
