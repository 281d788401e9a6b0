// Welding: merging vertices that sit at the same position (as an OBJ import splits
// them per face) so that area-weighted vertex normals shade smoothly across faces.
//
// Usage (snippet: examples/snippets/geometry_weld.cpp):
//
//     #include "prism/geometry/weld.hpp"
//     using namespace prism::geometry;
//     WeldResult smooth = weldVertices(split);  // merge by position
//     WeldOptions hard;
//     hard.creaseAngleDegrees = 30.0f;
//     WeldResult cube = weldVertices(splitCube, hard);  // keeps sharp edges
//     // smooth.mesh: welded mesh with recomputed normals
//     // smooth.newIndexOfOldVertex[i]: where input vertex i went
//
// Rules (both methods below give identical results):
//  * Positions are compared exactly with float ==, so -0.0 equals 0.0 and a vertex with
//    a NaN/Inf coordinate is never merged with anything.
//  * Each vertex has a direction: the normalised sum of the cross products of the
//    valid triangles that use it (for a split mesh: its face normal). With a crease
//    angle, a vertex joins a group at its position only if its direction is within
//    the crease angle of the group's first vertex; a vertex without a direction (only
//    degenerate faces) joins the first group at its position, and a group whose first
//    vertex has no direction accepts any vertex.
//  * With keepUvSeams (default) and uvs present, vertices also need equal uvs.
//  * Groups are tried in the order they were created; the first that accepts wins.
//    New vertex i is the i-th group created, in input order; it keeps the position and
//    uv of its first vertex. Triangles are kept (re-indexed), none are removed.
//
// weldVertices is O(n): an open-addressing hash table keyed on the float bit patterns.
// weldQuadraticReference is the createVertexNormals() search of the FUDGE shader thesis (§6.3) (every vertex
// compared against all earlier ones), O(n^2): for cross-checks and the benchmark only.
#pragma once

#include "prism/geometry/mesh.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace prism::geometry {

struct WeldOptions {
    // Merge only vertices whose face directions differ by at most this many degrees;
    // nullopt merges by position alone.
    std::optional<float> creaseAngleDegrees;
    // Keep vertices with different uvs apart (texture seams). Ignored without uvs.
    bool keepUvSeams = true;
    // Recompute area-weighted normals on the welded mesh; otherwise copy each group's
    // first normal (if the input had normals).
    bool recomputeNormals = true;
};

struct WeldResult {
    Mesh mesh;
    std::vector<std::uint32_t> newIndexOfOldVertex;  // one entry per input vertex
};

// O(n) welding with a hash table. Throws std::invalid_argument for an invalid mesh.
WeldResult weldVertices(const Mesh& mesh, const WeldOptions& options = {});

// The O(n^2) search of the FUDGE shader thesis (§6.3); same result as weldVertices.
WeldResult weldQuadraticReference(const Mesh& mesh, const WeldOptions& options = {});

}  // namespace prism::geometry
