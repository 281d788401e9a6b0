// Face normals and area-weighted vertex normals that never come out NaN.
//
// Usage (snippet: examples/snippets/geometry_normals.cpp):
//
//     #include "prism/geometry/normals.hpp"
//     using namespace prism::geometry;
//     NormalStats stats = computeVertexNormals(mesh);      // fills mesh.normals
//     Mesh flat = makeFlatShaded(mesh);                    // split per face, face normals
//     glm::vec3 n = safeNormalize(v, glm::vec3(0, 0, 1));  // unit vector or the fallback
//
// Area weighting: a vertex normal is the sum of the *unnormalised* cross products
// (b - a) x (c - a) of the triangles around it, then normalised. The length of a
// cross product is twice the triangle's area, so big triangles pull harder than
// small ones (the method of the FUDGE shader thesis §6.2).
//
// Robustness:
//  * Cross products and sums are computed in double, so no finite float input can
//    overflow or underflow them (the whole float range, denormals included).
//  * A triangle is *degenerate* and contributes nothing when a corner is NaN/Inf, when
//    it repeats an index, or when its area is zero relative to its size:
//    |cross| = 2 * area <= kDegenerateAreaRatio * (longest edge)^2, which catches
//    exactly and numerically collinear corners at any scale (a relative epsilon).
//  * A sum is only normalised when it is large relative to what went into it:
//    |sum| > kCancellationRatio * sum(|cross|) (faces that cancel, e.g. a two-sided
//    sheet, leave no direction).
//
// Fallback for a vertex with no valid face (or whose faces cancel), in this order:
//  1. the normalised sum of the unit normals of the vertices it shares a (degenerate)
//     triangle with, counting those that have a direction of their own: a NaN corner
//     in a good mesh takes its neighbours' direction;
//  2. the mesh's area-weighted average direction, if the mesh clearly faces one way
//     (|sum of all crosses| > kMeshDirectionRatio * sum of their lengths; a closed
//     mesh sums to zero and skips this step);
//  3. options.fallbackNormal, default (0, 0, 1) (itself replaced by (0, 0, 1) if not a
//     usable direction).
// Unreferenced vertices go through the same chain (they have no neighbours, so 2 or 3).
#pragma once

#include "prism/geometry/mesh.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace prism::geometry {

// 2 * area / (longest edge)^2 at or below which a triangle counts as degenerate
// (a triangle of aspect ratio beyond about a million to one).
inline constexpr double kDegenerateAreaRatio = 1e-6;
// |sum| / sum(|parts|) at or below which a sum of face crosses counts as cancelled.
inline constexpr double kCancellationRatio = 1e-6;
// |sum| / sum(|parts|) above which the whole mesh counts as facing one direction.
inline constexpr double kMeshDirectionRatio = 1e-2;

struct VertexNormalOptions {
    glm::vec3 fallbackNormal{0.0f, 0.0f, 1.0f};
};

struct NormalStats {
    std::size_t degenerateTriangles = 0;  // triangles that contributed nothing
    std::size_t fallbackVertices = 0;     // vertices that went through the fallback chain
};

// Unit vector in the direction of v, computed in double; `fallback` when v is zero or
// not finite. Every non-zero finite float vector (denormals included) normalises.
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback);

// (b - a) x (c - a) in double: twice the area, pointing to the CCW front side.
// Zero when any corner is not finite or the triangle is degenerate (see above).
glm::dvec3 triangleCrossProduct(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// One entry per triangle: triangleCrossProduct of its corners (zero for a degenerate
// triangle or one that repeats an index). Throws std::invalid_argument for an invalid mesh.
std::vector<glm::dvec3> faceCrossProducts(const Mesh& mesh);

// One unit normal per triangle. A degenerate triangle takes the normalised sum of its
// corners' area-weighted vertex normals, else options.fallbackNormal.
std::vector<glm::vec3> faceNormals(const Mesh& mesh, const VertexNormalOptions& options = {});

// Area-weighted unit vertex normals, one per position (never NaN; fallback above).
std::vector<glm::vec3> areaWeightedVertexNormals(const Mesh& mesh, const VertexNormalOptions& options = {},
                                                 NormalStats* stats = nullptr);

// Fills mesh.normals with areaWeightedVertexNormals and returns the statistics.
NormalStats computeVertexNormals(Mesh& mesh, const VertexNormalOptions& options = {});

// Flat shading: every triangle gets its own three vertices carrying its face normal.
Mesh makeFlatShaded(const Mesh& mesh, const VertexNormalOptions& options = {});

}  // namespace prism::geometry
