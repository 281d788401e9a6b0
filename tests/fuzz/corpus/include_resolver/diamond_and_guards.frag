#version 330 core
#include "left.glsl"
#include <right.glsl>
#include "guarded.glsl"
#include "guarded.glsl"
#include "once.glsl"
out vec4 frag;
void main() { frag = vec4(left() + right() + guarded() + once()); }
