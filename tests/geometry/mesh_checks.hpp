// Shared checks for the geometry tests: finiteness, unit normals, winding and
// closedness of meshes.
#pragma once

#include "prism/geometry/mesh.hpp"
#include "prism/geometry/weld.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace prism::geometry::testing {

inline bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline ::testing::AssertionResult hasUnitNormals(const Mesh& mesh, float tolerance = 1e-5f) {
    if (mesh.normals.size() != mesh.positions.size())
        return ::testing::AssertionFailure()
               << mesh.normals.size() << " normals for " << mesh.positions.size() << " positions";
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const glm::vec3 n = mesh.normals[i];
        if (!isFinite(n) || std::abs(glm::length(n) - 1.0f) > tolerance)
            return ::testing::AssertionFailure()
                   << "normal " << i << " = (" << n.x << ", " << n.y << ", " << n.z << ") is not a finite unit vector";
    }
    return ::testing::AssertionSuccess();
}

inline glm::dvec3 faceCross(const Mesh& mesh, std::size_t t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
    return glm::cross(b - a, c - a);
}

// Every triangle's CCW face normal agrees with its corners' vertex normals.
inline ::testing::AssertionResult windingMatchesNormals(const Mesh& mesh) {
    for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
        glm::dvec3 normals(0.0);
        for (int k = 0; k < 3; ++k) normals += glm::dvec3(mesh.normals[mesh.indices[3 * t + k]]);
        if (!(glm::dot(faceCross(mesh, t), normals) > 0.0))
            return ::testing::AssertionFailure() << "triangle " << t << " winds against its vertex normals";
    }
    return ::testing::AssertionSuccess();
}

// Divergence theorem: positive for a closed mesh whose faces wind CCW seen from outside.
inline double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < triangleCount(mesh); ++t) {
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

// Closed, consistently wound surface: after merging equal positions, every directed
// edge occurs exactly once and its reverse exactly once.
inline ::testing::AssertionResult isClosedAndConsistentlyWound(const Mesh& mesh) {
    Mesh geometryOnly;
    geometryOnly.positions = mesh.positions;
    geometryOnly.indices = mesh.indices;
    WeldOptions byPosition;
    byPosition.recomputeNormals = false;
    const Mesh welded = weldVertices(geometryOnly, byPosition).mesh;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
    for (std::size_t t = 0; t < triangleCount(welded); ++t)
        for (int k = 0; k < 3; ++k) ++directedEdges[{welded.indices[3 * t + k], welded.indices[3 * t + (k + 1) % 3]}];
    for (const auto& [edge, count] : directedEdges) {
        if (count != 1)
            return ::testing::AssertionFailure() << "edge " << edge.first << "->" << edge.second << " used " << count
                                                 << " times in the same direction";
        auto reverse = directedEdges.find({edge.second, edge.first});
        if (reverse == directedEdges.end())
            return ::testing::AssertionFailure() << "edge " << edge.first << "->" << edge.second
                                                 << " has no opposite edge (hole or flipped triangle)";
    }
    return ::testing::AssertionSuccess();
}

}  // namespace prism::geometry::testing
