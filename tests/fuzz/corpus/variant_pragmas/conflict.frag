#pragma prism variant FOG 0 1
#pragma prism variant FOG 1 2
#pragma prism variant DIRECTIONAL_LIGHTS 0 1
#include "lights.glsl"
//--filters
main:FOG=3
other:X=1
main:
:A=1
main:A=1,,B=
