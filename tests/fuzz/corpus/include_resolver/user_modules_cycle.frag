#include "user_a.glsl"
#include "cycle_a.glsl"
void main() {}
//--file
// user module
#pragma once
#include "user_b.glsl"
float a() { return 1.0; }
//--file
#include "plain.glsl"
#include "user_a.glsl"
