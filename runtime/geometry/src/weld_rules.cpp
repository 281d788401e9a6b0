// The merge rules shared by both welding methods and the assembly of the welded mesh.
#include "weld_rules.hpp"

#include "prism/geometry/normals.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <stdexcept>
#include <string>

namespace prism::geometry::detail {

namespace {

// Per vertex: the normalised sum of the valid cross products around it, or zero when
// it has no valid triangle or its triangles cancel (same test as the vertex normals).
std::vector<glm::vec3> vertexDirections(const Mesh& mesh) {
    const std::vector<glm::dvec3> crosses = faceCrossProducts(mesh);
    std::vector<glm::dvec3> sums(mesh.positions.size(), glm::dvec3(0.0));
    std::vector<double> lengthSums(mesh.positions.size(), 0.0);
    for (std::size_t t = 0; t < crosses.size(); ++t) {
        const double length = glm::length(crosses[t]);
        for (int corner = 0; corner < 3; ++corner) {
            sums[mesh.indices[3 * t + corner]] += crosses[t];
            lengthSums[mesh.indices[3 * t + corner]] += length;
        }
    }
    std::vector<glm::vec3> directions(sums.size(), glm::vec3(0.0f));
    for (std::size_t v = 0; v < sums.size(); ++v) {
        const double length = glm::length(sums[v]);
        if (length > 0.0 && length > kCancellationRatio * lengthSums[v]) directions[v] = glm::vec3(sums[v] / length);
    }
    return directions;
}

bool isZero(const glm::vec3& v) {
    return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f;
}

}  // namespace

WeldRules::WeldRules(const Mesh& mesh, const WeldOptions& options) : mesh_(mesh) {
    requireValidTriangles(mesh, "weld");
    const std::size_t vertices = mesh.positions.size();
    if (!mesh.uvs.empty() && mesh.uvs.size() != vertices)
        throw std::invalid_argument("weld: invalid mesh: " + std::to_string(mesh.uvs.size()) + " uvs for " +
                                    std::to_string(vertices) + " positions");
    // Normals are read only when they are carried over instead of recomputed.
    if (!options.recomputeNormals && !mesh.normals.empty() && mesh.normals.size() != vertices)
        throw std::invalid_argument("weld: invalid mesh: " + std::to_string(mesh.normals.size()) + " normals for " +
                                    std::to_string(vertices) + " positions");
    compareUvs_ = options.keepUvSeams && !mesh.uvs.empty();
    if (options.creaseAngleDegrees) {
        const float degrees = *options.creaseAngleDegrees;
        if (!(degrees >= 0.0f))
            throw std::invalid_argument("weld: the crease angle must be a number >= 0 degrees, got " +
                                        std::to_string(degrees));
        if (degrees < 180.0f) {
            useCrease_ = true;
            // A little slack so that an angle equal to the crease (up to rounding) merges.
            minimumCosine_ = static_cast<float>(std::cos(glm::radians(static_cast<double>(degrees)))) - 1e-6f;
            directions_ = vertexDirections(mesh);
        }
    }
}

bool WeldRules::mayJoin(std::uint32_t groupFirst, std::uint32_t candidate) const {
    if (compareUvs_ && mesh_.uvs[groupFirst] != mesh_.uvs[candidate]) return false;
    if (!useCrease_) return true;
    const glm::vec3& groupDirection = directions_[groupFirst];
    const glm::vec3& candidateDirection = directions_[candidate];
    if (isZero(candidateDirection) || isZero(groupDirection)) return true;  // no direction: no crease
    return glm::dot(groupDirection, candidateDirection) >= minimumCosine_;
}

WeldResult buildWeldResult(const Mesh& mesh, std::vector<std::uint32_t> groupOfVertex,
                           const std::vector<std::uint32_t>& firstVertexOfGroup, const WeldOptions& options) {
    WeldResult result;
    Mesh& welded = result.mesh;
    const std::size_t groups = firstVertexOfGroup.size();
    welded.positions.resize(groups);
    if (!mesh.uvs.empty()) welded.uvs.resize(groups);
    for (std::size_t g = 0; g < groups; ++g) {
        welded.positions[g] = mesh.positions[firstVertexOfGroup[g]];
        if (!mesh.uvs.empty()) welded.uvs[g] = mesh.uvs[firstVertexOfGroup[g]];
    }
    welded.indices.resize(mesh.indices.size());
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) welded.indices[i] = groupOfVertex[mesh.indices[i]];
    if (options.recomputeNormals) {
        computeVertexNormals(welded);
    } else if (!mesh.normals.empty()) {
        welded.normals.resize(groups);
        for (std::size_t g = 0; g < groups; ++g) welded.normals[g] = mesh.normals[firstVertexOfGroup[g]];
    }
    result.newIndexOfOldVertex = std::move(groupOfVertex);
    return result;
}

}  // namespace prism::geometry::detail
