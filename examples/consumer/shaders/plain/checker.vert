// Checker: passes the texture coordinates on for the checkerboard.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
in vec2 a_uv;
out vec2 v_uv;

void main() {
    v_uv = a_uv;
    gl_Position = clipPosition(eyePosition(a_position));
}
