// ground: the rain scene's ground plane or terrain, lit in world space.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
in vec3 a_normal;
out vec3 v_worldPosition;
out vec3 v_worldNormal;

void main() {
    vec4 world = u_world * vec4(a_position, 1.0);
    v_worldPosition = world.xyz;
    v_worldNormal = mat3(u_world) * a_normal;  // the scene uses rigid world matrices
    gl_Position = u_projection * u_view * world;
}
