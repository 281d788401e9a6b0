// Smooth: writes the interpolated vertex colour (fogged in the FOG variant).
#include <version.glsl>
#include <fragment_output.glsl>
#include <fog_fragment.glsl>

in vec4 v_color;

void main() {
    frag = vec4(fogged(v_color.rgb), v_color.a);
}
