// Smooth: diffuse lighting per vertex from area-weighted vertex normals; the colour
// is interpolated over the triangle.
#include <version.glsl>
#include <vertex_lighting.glsl>

out vec4 v_color;

void main() {
    v_color = litVertexColor(false);
}
