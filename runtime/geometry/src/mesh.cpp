// Mesh helpers: bounds, structural validation and splitting vertices per face.
#include "prism/geometry/mesh.hpp"

#include "finite.hpp"

#include <glm/common.hpp>

#include <cmath>
#include <stdexcept>

namespace prism::geometry {

Bounds computeBounds(const Mesh& mesh) {
    Bounds bounds;
    bool any = false;
    for (const glm::vec3& p : mesh.positions) {
        if (!detail::isFinite(p)) continue;
        if (!any) {
            bounds.min = bounds.max = p;
            any = true;
        } else {
            bounds.min = glm::min(bounds.min, p);
            bounds.max = glm::max(bounds.max, p);
        }
    }
    return bounds;
}

std::optional<std::string> findTriangleProblem(const Mesh& mesh) {
    const std::size_t vertices = mesh.positions.size();
    if (mesh.indices.size() % 3 != 0)
        return "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3";
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= vertices)
            return "triangle " + std::to_string(i / 3) + " uses vertex " + std::to_string(mesh.indices[i]) +
                   " but the mesh has " + std::to_string(vertices) + " positions";
    }
    return std::nullopt;
}

std::optional<std::string> findMeshProblem(const Mesh& mesh) {
    const std::size_t vertices = mesh.positions.size();
    if (!mesh.normals.empty() && mesh.normals.size() != vertices)
        return std::to_string(mesh.normals.size()) + " normals for " + std::to_string(vertices) + " positions";
    if (!mesh.uvs.empty() && mesh.uvs.size() != vertices)
        return std::to_string(mesh.uvs.size()) + " uvs for " + std::to_string(vertices) + " positions";
    return findTriangleProblem(mesh);
}

void requireValidMesh(const Mesh& mesh, const char* what) {
    if (auto problem = findMeshProblem(mesh))
        throw std::invalid_argument(std::string(what) + ": invalid mesh: " + *problem);
}

void requireValidTriangles(const Mesh& mesh, const char* what) {
    if (auto problem = findTriangleProblem(mesh))
        throw std::invalid_argument(std::string(what) + ": invalid mesh: " + *problem);
}

Mesh splitVerticesPerFace(const Mesh& mesh) {
    requireValidMesh(mesh, "splitVerticesPerFace");
    const std::size_t corners = mesh.indices.size();
    if (corners > std::size_t(0xFFFFFFFFu))
        throw std::invalid_argument("splitVerticesPerFace: more than 2^32 triangle corners do not fit 32-bit indices");
    Mesh split;
    split.positions.reserve(corners);
    if (!mesh.normals.empty()) split.normals.reserve(corners);
    if (!mesh.uvs.empty()) split.uvs.reserve(corners);
    split.indices.reserve(corners);
    for (std::size_t corner = 0; corner < corners; ++corner) {
        const std::uint32_t source = mesh.indices[corner];
        split.positions.push_back(mesh.positions[source]);
        if (!mesh.normals.empty()) split.normals.push_back(mesh.normals[source]);
        if (!mesh.uvs.empty()) split.uvs.push_back(mesh.uvs[source]);
        split.indices.push_back(static_cast<std::uint32_t>(corner));
    }
    return split;
}

}  // namespace prism::geometry
