// Procedural meshes for tests, examples and the gallery. All are centred at the
// origin, deterministic, have unit normals pointing outward (up for the grid) and
// counter-clockwise front faces seen from outside.
//
// Usage (snippet: examples/snippets/geometry_procedural_meshes.cpp):
//
//     #include "prism/geometry/procedural_meshes.hpp"
//     using namespace prism::geometry;
//     Mesh cube = makeCube();                       // 24 vertices, flat faces, uvs
//     Mesh sphere = makeUvSphere(1.0f, 16, 32);     // rings x segments, uvs
//     Mesh ico = makeIcosphere(1.0f, 3);            // 10 * 4^3 + 2 shared vertices
//     Mesh torus = makeTorus(1.0f, 0.35f, 48, 24);  // uvs
//     Mesh grid = makeGrid(2.0f, 2.0f, 8, 8);       // XZ plane facing +Y, uvs
//     Mesh knot = makeTrefoilKnot();                // ribbed tube: concave grooves
//
// Sizes and counts are validated: a non-finite or non-positive size or a count below
// the minimum throws std::invalid_argument naming the parameter.
#pragma once

#include "prism/geometry/mesh.hpp"

#include <cstdint>

namespace prism::geometry {

// Axis-aligned cube with the given edge length: 6 faces x 4 vertices, 12 triangles,
// flat per-face normals, uvs covering [0,1]^2 on every face.
Mesh makeCube(float edgeLength = 1.0f);

// Latitude/longitude sphere: `rings` >= 2 bands from pole to pole, `segments` >= 3
// around. Poles have one vertex per segment (every vertex is used); the seam column is
// duplicated for uvs. Vertices: 2*segments + (rings-1)*(segments+1).
// Triangles: 2*segments*(rings-1).
Mesh makeUvSphere(float radius = 1.0f, std::uint32_t rings = 16, std::uint32_t segments = 32);

// Subdivided icosahedron, `level` 0..7, every vertex shared (no uvs, no seams).
// Vertices: 10*4^level + 2, triangles: 20*4^level.
Mesh makeIcosphere(float radius = 1.0f, std::uint32_t level = 2);
std::uint32_t icosphereVertexCount(std::uint32_t level);

// Torus around the Y axis: ring of radius `majorRadius` (> minorRadius) with a tube of
// radius `minorRadius`. Vertices: (majorSegments+1)*(minorSegments+1) (uv seams).
// Triangles: 2*majorSegments*minorSegments; both segment counts >= 3.
Mesh makeTorus(float majorRadius = 1.0f, float minorRadius = 0.35f, std::uint32_t majorSegments = 48,
               std::uint32_t minorSegments = 24);

// Flat grid in the XZ plane facing +Y, `width` along X, `depth` along Z, with
// `columns` x `rows` >= 1 cells of two triangles each; uvs span [0,1]^2.
Mesh makeGrid(float width = 2.0f, float depth = 2.0f, std::uint32_t columns = 8, std::uint32_t rows = 8);

// A tube along a trefoil knot with `ridges` grooves twisting along it: a closed,
// curved surface with saddles and concave grooves that shows the difference between
// flat, Gouraud and Phong shading. Vertices: pathSegments*tubeSegments (no seams, no
// uvs); normals are the area-weighted vertex normals of the mesh itself. Fits in a
// sphere of radius about 1.
struct TrefoilKnotShape {
    std::uint32_t pathSegments = 256;  // along the knot, >= 24
    std::uint32_t tubeSegments = 32;   // around the tube, >= 3
    float tubeRadius = 0.12f;          // in (0, 0.15]: thicker tubes would intersect
    std::uint32_t ridges = 6;          // grooves around the tube (0 = smooth tube)
    float ridgeDepth = 0.18f;          // relative to the radius, in [0, 0.25]
    std::uint32_t ridgeTwists = 3;     // turns of the grooves around the tube, like a rope
};
Mesh makeTrefoilKnot(const TrefoilKnotShape& shape = {});

}  // namespace prism::geometry
