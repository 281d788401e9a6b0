// Unicolor: positions only; every fragment gets the material colour.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
#if FOG
out float v_fogDistance;
#endif

void main() {
    vec4 eye = eyePosition(a_position);
#if FOG
    v_fogDistance = length(eye.xyz);
#endif
    gl_Position = clipPosition(eye);
}
