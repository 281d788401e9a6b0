// The indexed triangle mesh that the whole geometry library works on, plus small
// helpers to count, bound, validate and split it.
//
// A Mesh is a triangle list: every three entries of `indices` form one triangle whose
// corners run counter-clockwise when seen from the front (outside). Attribute arrays
// are parallel: `normals` and `uvs` are either empty or hold exactly one entry per
// position.
//
// Usage (snippet: examples/snippets/geometry_mesh.cpp):
//
//     #include "prism/geometry/mesh.hpp"
//     #include "prism/geometry/procedural_meshes.hpp"
//     prism::geometry::Mesh mesh = prism::geometry::makeIcosphere(1.0f, 3);
//     std::size_t triangles = prism::geometry::triangleCount(mesh);
//     prism::geometry::Bounds box = prism::geometry::computeBounds(mesh);
//     if (auto problem = prism::geometry::findMeshProblem(mesh)) { /* report *problem */
//     }
//     prism::geometry::Mesh split = prism::geometry::splitVerticesPerFace(mesh);  // as OBJ import gives
//
// Nothing here needs a GL context.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace prism::geometry {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // empty, or one unit normal per position
    std::vector<glm::vec2> uvs;          // empty, or one texture coordinate per position
    std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise front faces
};

// Axis-aligned box. An empty box (no finite position) has min > max.
struct Bounds {
    glm::vec3 min{1.0f, 1.0f, 1.0f};
    glm::vec3 max{-1.0f, -1.0f, -1.0f};

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 center() const { return isEmpty() ? glm::vec3(0.0f) : (min + max) * 0.5f; }
    glm::vec3 size() const { return isEmpty() ? glm::vec3(0.0f) : max - min; }
};

inline std::size_t vertexCount(const Mesh& mesh) {
    return mesh.positions.size();
}
inline std::size_t triangleCount(const Mesh& mesh) {
    return mesh.indices.size() / 3;
}

// Bounds of all finite positions (NaN/Inf positions are skipped).
Bounds computeBounds(const Mesh& mesh);

// Describes the first structural problem (index count not a multiple of 3, an index
// out of range, attribute arrays of the wrong length), or nothing for a valid mesh.
std::optional<std::string> findMeshProblem(const Mesh& mesh);
// Only the triangles: index count and range (what computing normals needs).
std::optional<std::string> findTriangleProblem(const Mesh& mesh);

// Throw std::invalid_argument naming `what` and the problem.
void requireValidMesh(const Mesh& mesh, const char* what);
void requireValidTriangles(const Mesh& mesh, const char* what);

// Gives every triangle its own three vertices (as an OBJ importer does): positions,
// normals and uvs are copied, indices become 0, 1, 2, ... Throws like requireValidMesh.
Mesh splitVerticesPerFace(const Mesh& mesh);

}  // namespace prism::geometry
