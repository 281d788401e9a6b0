// The usage example of prism/geometry/procedural_meshes.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/geometry/procedural_meshes.hpp"
using namespace prism::geometry;
// [/snippet]

int main() {
    // [snippet]
    Mesh cube = makeCube();                       // 24 vertices, flat faces, uvs
    Mesh sphere = makeUvSphere(1.0f, 16, 32);     // rings x segments, uvs
    Mesh ico = makeIcosphere(1.0f, 3);            // 10 * 4^3 + 2 shared vertices
    Mesh torus = makeTorus(1.0f, 0.35f, 48, 24);  // uvs
    Mesh grid = makeGrid(2.0f, 2.0f, 8, 8);       // XZ plane facing +Y, uvs
    Mesh knot = makeTrefoilKnot();                // ribbed tube: concave grooves
    // [/snippet]
    for (const Mesh* m : {&sphere, &torus, &grid, &knot})
        if (m->positions.empty()) return 1;
    return cube.positions.size() == 24 && ico.positions.size() == 10 * 64 + 2 ? 0 : 1;
}
