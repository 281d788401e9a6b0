// Unicolor: the material colour, unlit.
#include <version.glsl>
#include <material.glsl>
#include <fragment_output.glsl>

void main() {
    frag = vec4(u_color.rgb, 1.0);
}
