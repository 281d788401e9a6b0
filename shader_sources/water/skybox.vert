// Skybox: a unit cube around the camera (rotation of the view only), drawn at the far
// plane; the cube position is the cube-map direction.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
out vec3 v_direction;

void main() {
    v_direction = a_position;
    vec4 clip = u_projection * vec4(mat3(u_view) * a_position, 1.0);
    gl_Position = clip.xyww;
}
