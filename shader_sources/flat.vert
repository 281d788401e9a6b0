// Flat: one colour per triangle. The mesh carries face normals (vertices split per
// face); the lit colour of the provoking vertex is passed on `flat`, unchanged over
// the triangle. Diffuse only (no specular term).
#include <version.glsl>
#include <vertex_lighting.glsl>

flat out vec4 v_color;

void main() {
    v_color = litVertexColor(false);
}
