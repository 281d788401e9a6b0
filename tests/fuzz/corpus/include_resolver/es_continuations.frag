#version 300 es
precision mediump float;
#pragma prism variant LIGHTS 1 2 4
#include "variant.glsl"
#line 10
/* block
 comment */ #define X \
  1
#if X
void main() {}
#endif
