// Gouraud: writes the interpolated vertex colour.
#include <version.glsl>
#include <fragment_output.glsl>

in vec4 v_color;

void main() {
    frag = v_color;
}
