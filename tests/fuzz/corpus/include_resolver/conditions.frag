#version 410 core
#define A 3
#define B (A * 2 + 1)
#if defined(FAST) && (B % 4 == 3) ? 1 : 0
#include "conditional.glsl"
#elif !defined EMPTY || 0x10 > 017u
#include "missing.glsl"
#else
#error unreachable
#endif
#ifdef A
#undef A
#endif
#ifndef A
#if (1 << 4) - ~0 == 17 && -1 < 0 || 5 / 0
#include "plain.glsl"
#endif
#endif
void main() {}
