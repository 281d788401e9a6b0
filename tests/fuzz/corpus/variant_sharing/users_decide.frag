#version 330 core
#include "user_a.glsl"
out vec4 o;
void main() { o = vec4(float(A + B)); }

//--file
#if defined(B) && B == 2 || A
#define PICK 1
#endif
#ifdef PICK
#include "user_b.glsl"
#else
float b() { return 0.0; }
#endif

//--file
#pragma once
float b() { return float(K); }
