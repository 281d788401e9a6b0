// Gouraud: diffuse and specular lighting per vertex, interpolated. It cannot show a
// highlight that falls inside a triangle; see docs/tradeoffs.md for what that costs.
// The vertex position (never the normal) is transformed to eye space, and the view
// vector runs from it to the camera (docs/references.md lists the bugs this avoids).
#include <version.glsl>
#include <vertex_lighting.glsl>

out vec4 v_color;

void main() {
    v_color = litVertexColor(true);
}
