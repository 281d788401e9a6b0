// Tinted unicolor: positions only; every fragment gets the tinted material colour.
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;

void main() {
    gl_Position = clipPosition(eyePosition(a_position));
}
