// The usage example of prism/geometry/mesh.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/geometry/mesh.hpp"
#include "prism/geometry/procedural_meshes.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::geometry::Mesh mesh = prism::geometry::makeIcosphere(1.0f, 3);
    std::size_t triangles = prism::geometry::triangleCount(mesh);
    prism::geometry::Bounds box = prism::geometry::computeBounds(mesh);
    if (auto problem = prism::geometry::findMeshProblem(mesh)) { /* report *problem */
    }
    prism::geometry::Mesh split = prism::geometry::splitVerticesPerFace(mesh);  // as OBJ import gives
    // [/snippet]
    return triangles == 1280 && box.max.x > 0.99f && split.positions.size() == 3 * triangles ? 0 : 1;
}
