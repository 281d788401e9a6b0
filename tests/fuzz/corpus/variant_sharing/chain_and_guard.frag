#version 330 core
#pragma prism variant B 0 1 2
#include "chain.glsl"
#include <guarded.glsl>
#include "once.glsl"
#if K == 2
#include "values.glsl"
#endif
out vec4 o;
void main() { o = vec4(g() + once() + float(K)); }
