// Diffraction material: eye-space position, normal and groove-across tangent for the fragment
// stage (u_diffractionTangent is the object-space direction across the grooves).
#include <version.glsl>
#include <transforms.glsl>

uniform vec3 u_diffractionTangent;

in vec3 a_position;
in vec3 a_normal;
out vec3 v_eyePosition;
out vec3 v_eyeNormal;
out vec3 v_eyeTangent;

void main() {
    vec4 eye = eyePosition(a_position);
    v_eyePosition = eye.xyz;
    v_eyeNormal = u_normal * a_normal;
    v_eyeTangent = mat3(u_view) * (mat3(u_world) * u_diffractionTangent);
    gl_Position = clipPosition(eye);
}
