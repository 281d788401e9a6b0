// Tinted Phong: passes the eye-space position and normal on; lighting and the tint
// are applied per fragment.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
in vec3 a_normal;
out vec3 v_eyePosition;
out vec3 v_eyeNormal;

void main() {
    vec4 eye = eyePosition(a_position);
    v_eyePosition = eye.xyz;
    v_eyeNormal = u_normal * a_normal;
    gl_Position = clipPosition(eye);
}
