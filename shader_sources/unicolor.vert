// Unicolor: positions only; every fragment gets the material colour.
#include <version.glsl>
#include <transforms.glsl>
#include <fog_vertex.glsl>

in vec3 a_position;

void main() {
    vec4 eye = eyePosition(a_position);
    passFogDistance(eye);
    gl_Position = clipPosition(eye);
}
