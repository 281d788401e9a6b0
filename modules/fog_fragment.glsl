// Provides: fogged(colour), the fragment side of the FOG variant: with FOG = 1 it
// applies fog.glsl's exponential fog at the distance fog_vertex.glsl passed on; with
// FOG = 0 it returns the colour unchanged and declares no fog varying or uniform.
#pragma prism variant FOG

#if FOG
#include <fog.glsl>
in float v_fogDistance;
#endif

vec3 fogged(vec3 color) {
#if FOG
    return applyFog(color, v_fogDistance);
#else
    return color;
#endif
}
