// Flat: writes the triangle's colour.
#include <version.glsl>
#include <fragment_output.glsl>

flat in vec4 v_color;

void main() {
    frag = v_color;
}
