// Tinted unicolor: the material colour with the consumer's tint, unlit.
#include <version.glsl>
#include <material.glsl>
#include <fragment_output.glsl>
#include <tint.glsl>

void main() {
    frag = vec4(applyTint(u_color.rgb), u_color.a);
}
