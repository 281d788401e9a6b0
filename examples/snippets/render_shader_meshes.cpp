// The usage example of prism/render/shader_meshes.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/render/shader_meshes.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::geometry::Mesh m = prism::render::namedMesh("torus", /*subdivision*/ 3);
    prism::geometry::Mesh ready = prism::render::meshForShader("flat", m);  // split per face, face normals
    // [/snippet]
    return ready.positions.size() == 3 * prism::geometry::triangleCount(m) ? 0 : 1;
}
