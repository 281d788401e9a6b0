#version 330 core
#if A
#error A is on
#endif
#if B / (A + 1) > 0
float f;
#endif
void main() {}
