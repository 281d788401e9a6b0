// Diffraction material: eye-space position, normal and groove-across tangent for the fragment
// stage (u_diffractionTangent is the object-space direction across the grooves; with
// u_diffractionRadial = 1 it is the direction away from the object's y axis instead, so the
// grooves are circles about that axis, like a CD's tracks).
#include <version.glsl>
#include <transforms.glsl>

uniform vec3 u_diffractionTangent;
uniform float u_diffractionRadial;

in vec3 a_position;
in vec3 a_normal;
out vec3 v_eyePosition;
out vec3 v_eyeNormal;
out vec3 v_eyeTangent;

void main() {
    vec4 eye = eyePosition(a_position);
    v_eyePosition = eye.xyz;
    v_eyeNormal = u_normal * a_normal;
    // (x, 0, z) is linear in the position, so interpolating it gives each fragment its own radial direction.
    vec3 across = u_diffractionRadial > 0.5 ? vec3(a_position.x, 0.0, a_position.z) : u_diffractionTangent;
    v_eyeTangent = mat3(u_view) * (mat3(u_world) * across);
    gl_Position = clipPosition(eye);
}
