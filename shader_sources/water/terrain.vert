// Terrain: the height-map mesh in world space; the per-vertex colour (a_color) is the
// albedo chosen on the CPU from slope, height and permeability (runtime/water
// terrain_mesh.cpp), a_uv the cell centre in the water-depth texture.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
in vec3 a_normal;
in vec2 a_uv;
in vec4 a_color;
out vec3 v_worldNormal;
out vec3 v_eyePosition;
out vec3 v_albedo;
out vec2 v_uv;

void main() {
    vec4 world = u_world * vec4(a_position, 1.0);
    vec4 eye = u_view * world;
    v_worldNormal = mat3(u_world) * a_normal;
    v_eyePosition = eye.xyz;
    v_albedo = a_color.rgb;
    v_uv = a_uv;
    gl_Position = clipPosition(eye);
}
