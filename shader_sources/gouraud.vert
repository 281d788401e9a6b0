// Gouraud: diffuse and specular lighting per vertex, interpolated. It cannot show a
// highlight that falls inside a triangle; see docs/tradeoffs.md for what that costs.
// The vertex position (never the normal) is transformed to eye space, and the view
// vector runs from it to the camera (docs/references.md lists the bugs this avoids).
#include <version.glsl>
#include <transforms.glsl>
#include <normals.glsl>
#include <lighting.glsl>

in vec3 a_position;
in vec3 a_normal;
out vec4 v_color;
#if FOG
out float v_fogDistance;
#endif

void main() {
    vec4 eye = eyePosition(a_position);
    v_color = vec4(shade(eye.xyz, eyeNormal(a_normal), true), 1.0);
#if FOG
    v_fogDistance = length(eye.xyz);
#endif
    gl_Position = clipPosition(eye);
}
