// Unicolor: the material colour, unlit.
#pragma prism variant FOG
#include <version.glsl>
#include <material.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

#if FOG
in float v_fogDistance;
#endif

void main() {
    vec3 color = u_color.rgb;
#if FOG
    color = applyFog(color, v_fogDistance);
#endif
    frag = vec4(color, 1.0);
}
