// Unicolor: the material colour, unlit (fogged in the FOG variant).
#include <version.glsl>
#include <material.glsl>
#include <fragment_output.glsl>
#include <fog_fragment.glsl>

void main() {
    frag = vec4(fogged(u_color.rgb), 1.0);
}
