// Provides: passFogDistance(eyePosition), the vertex side of the FOG variant: declares
// the v_fogDistance varying and writes the eye distance only when FOG is 1, so a
// variant without fog has neither. Pair it with fog_fragment.glsl in the fragment stage.
#pragma prism variant FOG

#if FOG
out float v_fogDistance;
#endif

void passFogDistance(vec4 eyePosition) {
#if FOG
    v_fogDistance = length(eyePosition.xyz);
#endif
}
