// Provides: litVertexColor(withSpecular), the whole vertex stage of the per-vertex lit
// shaders (flat, smooth, Gouraud): the eye-space position (of a_position, never the
// normal) and normal, the lit colour from lighting.glsl, the clip position and the
// FOG variant's distance (fog_vertex.glsl). The stage only declares how v_color is
// interpolated (`flat out` or `out`) and whether the specular term is wanted.
#include <transforms.glsl>
#include <normals.glsl>
#include <lighting.glsl>
#include <fog_vertex.glsl>

in vec3 a_position;
in vec3 a_normal;

vec4 litVertexColor(bool withSpecular) {
    vec4 eye = eyePosition(a_position);
    passFogDistance(eye);
    gl_Position = clipPosition(eye);
    return vec4(shade(eye.xyz, eyeNormal(a_normal), withSpecular), 1.0);
}
