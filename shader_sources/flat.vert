// Flat: one colour per triangle. The mesh carries face normals (vertices split per
// face); the lit colour of the provoking vertex is passed on `flat`, unchanged over
// the triangle. Diffuse only (no specular term).
#include <version.glsl>
#include <transforms.glsl>
#include <normals.glsl>
#include <lighting.glsl>

in vec3 a_position;
in vec3 a_normal;
flat out vec4 v_color;
#if FOG
out float v_fogDistance;
#endif

void main() {
    vec4 eye = eyePosition(a_position);
    v_color = vec4(shade(eye.xyz, eyeNormal(a_normal), false), 1.0);
#if FOG
    v_fogDistance = length(eye.xyz);
#endif
    gl_Position = clipPosition(eye);
}
