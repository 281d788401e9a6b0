#pragma prism variant BLINN
#pragma prism variant FOG
#pragma prism variant SHADOWS 0 1 2
#include "lights.glsl"
void main() {}
//--filters
main:BLINN=1,SHADOWS=2
*:FOG=0
main:DIRECTIONAL_LIGHTS=4
