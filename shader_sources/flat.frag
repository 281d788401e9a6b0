// Flat: writes the triangle's colour.
#pragma prism variant FOG
#include <version.glsl>
#include <fragment_output.glsl>
#if FOG
#include <fog.glsl>
#endif

flat in vec4 v_color;

#if FOG
in float v_fogDistance;
#endif

void main() {
    frag = v_color;
#if FOG
    frag.rgb = applyFog(frag.rgb, v_fogDistance);
#endif
}
