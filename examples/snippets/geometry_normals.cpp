// The usage example of prism/geometry/normals.hpp, compiled and run by tests/snippets.
#include <cmath>

#include "prism/geometry/procedural_meshes.hpp"
// [snippet]
#include "prism/geometry/normals.hpp"
using namespace prism::geometry;
// [/snippet]

int main() {
    Mesh mesh = makeIcosphere(1.0f, 1);
    mesh.normals.clear();
    const glm::vec3 v(0.0f);  // a zero vector: safeNormalize gives the fallback
    // [snippet]
    NormalStats stats = computeVertexNormals(mesh);      // fills mesh.normals
    Mesh flat = makeFlatShaded(mesh);                    // split per face, face normals
    glm::vec3 n = safeNormalize(v, glm::vec3(0, 0, 1));  // unit vector or the fallback
    // [/snippet]
    (void)stats;
    return mesh.normals.size() == mesh.positions.size() && flat.normals.size() == flat.positions.size() &&
                   n == glm::vec3(0, 0, 1)
               ? 0
               : 1;
}
