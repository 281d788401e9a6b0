// The usage example of prism/geometry/weld.hpp, compiled and run by tests/snippets.
#include "prism/geometry/mesh.hpp"
#include "prism/geometry/procedural_meshes.hpp"
// [snippet]
#include "prism/geometry/weld.hpp"
using namespace prism::geometry;
// [/snippet]

int main() {
    const Mesh split = splitVerticesPerFace(makeIcosphere(1.0f, 2));  // as an OBJ import gives
    const Mesh splitCube = splitVerticesPerFace(makeCube());
    // [snippet]
    WeldResult smooth = weldVertices(split);  // merge by position
    WeldOptions hard;
    hard.creaseAngleDegrees = 30.0f;
    WeldResult cube = weldVertices(splitCube, hard);  // keeps sharp edges
    // smooth.mesh: welded mesh with recomputed normals
    // smooth.newIndexOfOldVertex[i]: where input vertex i went
    // [/snippet]
    return smooth.mesh.positions.size() == 162 && cube.mesh.positions.size() == 24 ? 0 : 1;
}
