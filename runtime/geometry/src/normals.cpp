// Face normals and area-weighted vertex normals with a defined fallback (see
// prism/geometry/normals.hpp for the rules).
#include "prism/geometry/normals.hpp"

#include "finite.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace prism::geometry {

namespace {

const glm::vec3 kDefaultFallback{0.0f, 0.0f, 1.0f};

// Unit vector of `sum` if it is clearly longer than `reference` * ratio (no
// cancellation, no division by ~0); nullopt otherwise.
std::optional<glm::vec3> significantDirection(const glm::dvec3& sum, double reference, double ratio) {
    const double length = glm::length(sum);
    if (!(length > 0.0) || !std::isfinite(length) || !(length > ratio * reference)) return std::nullopt;
    return glm::vec3(sum / length);
}

glm::dvec3 crossOfTriangle(const Mesh& mesh, std::size_t triangle) {
    const std::uint32_t a = mesh.indices[3 * triangle];
    const std::uint32_t b = mesh.indices[3 * triangle + 1];
    const std::uint32_t c = mesh.indices[3 * triangle + 2];
    if (a == b || b == c || a == c) return glm::dvec3(0.0);
    return triangleCrossProduct(mesh.positions[a], mesh.positions[b], mesh.positions[c]);
}

bool isZero(const glm::dvec3& v) {
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

}  // namespace

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    if (!detail::isFinite(v)) return fallback;
    const glm::dvec3 d(v);
    const double length = glm::length(d);  // no overflow or underflow for float input
    if (!(length > 0.0)) return fallback;
    return glm::vec3(d / length);
}

glm::dvec3 triangleCrossProduct(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    if (!detail::isFinite(a) || !detail::isFinite(b) || !detail::isFinite(c)) return glm::dvec3(0.0);
    const glm::dvec3 pa(a), pb(b), pc(c);
    const glm::dvec3 ab = pb - pa, ac = pc - pa, bc = pc - pb;
    const glm::dvec3 cross = glm::cross(ab, ac);
    const double longestEdgeSquared = std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(bc, bc)});
    const double crossSquared = glm::dot(cross, cross);
    if (!(crossSquared > kDegenerateAreaRatio * kDegenerateAreaRatio * longestEdgeSquared * longestEdgeSquared))
        return glm::dvec3(0.0);
    return cross;
}

std::vector<glm::dvec3> faceCrossProducts(const Mesh& mesh) {
    requireValidTriangles(mesh, "faceCrossProducts");
    std::vector<glm::dvec3> crosses(triangleCount(mesh));
    for (std::size_t t = 0; t < crosses.size(); ++t) crosses[t] = crossOfTriangle(mesh, t);
    return crosses;
}

std::vector<glm::vec3> areaWeightedVertexNormals(const Mesh& mesh, const VertexNormalOptions& options,
                                                 NormalStats* stats) {
    requireValidTriangles(mesh, "areaWeightedVertexNormals");
    const glm::vec3 fallback = safeNormalize(options.fallbackNormal, kDefaultFallback);
    const std::size_t vertices = mesh.positions.size();
    const std::size_t triangles = triangleCount(mesh);
    NormalStats localStats;

    // Pass 1: sum the unnormalised cross products per vertex, and their lengths.
    std::vector<glm::dvec3> sums(vertices, glm::dvec3(0.0));
    std::vector<double> lengthSums(vertices, 0.0);
    glm::dvec3 meshSum(0.0);
    double meshLengthSum = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 cross = crossOfTriangle(mesh, t);
        if (isZero(cross)) {
            ++localStats.degenerateTriangles;
            continue;
        }
        const double length = glm::length(cross);
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t v = mesh.indices[3 * t + corner];
            sums[v] += cross;
            lengthSums[v] += length;
        }
        meshSum += cross;
        meshLengthSum += length;
    }

    std::vector<glm::vec3> normals(vertices);
    std::vector<std::uint8_t> hasOwnDirection(vertices, 0);
    for (std::size_t v = 0; v < vertices; ++v) {
        if (auto direction = significantDirection(sums[v], lengthSums[v], kCancellationRatio)) {
            normals[v] = *direction;
            hasOwnDirection[v] = 1;
        } else {
            ++localStats.fallbackVertices;
        }
    }

    if (localStats.fallbackVertices > 0) {
        // Fallback 1: the unit normals of the vertices sharing a triangle with it.
        std::vector<glm::dvec3> neighbourSums(vertices, glm::dvec3(0.0));
        std::vector<double> neighbourCounts(vertices, 0.0);
        for (std::size_t t = 0; t < triangles; ++t) {
            for (int corner = 0; corner < 3; ++corner) {
                const std::uint32_t v = mesh.indices[3 * t + corner];
                if (hasOwnDirection[v]) continue;
                for (int other = 1; other <= 2; ++other) {
                    const std::uint32_t w = mesh.indices[3 * t + (corner + other) % 3];
                    if (w == v || !hasOwnDirection[w]) continue;
                    neighbourSums[v] += glm::dvec3(normals[w]);
                    neighbourCounts[v] += 1.0;
                }
            }
        }
        // Fallback 2: the mesh's average direction, if it clearly has one; else 3.
        const glm::vec3 meshDirection =
            significantDirection(meshSum, meshLengthSum, kMeshDirectionRatio).value_or(fallback);
        for (std::size_t v = 0; v < vertices; ++v) {
            if (hasOwnDirection[v]) continue;
            normals[v] =
                significantDirection(neighbourSums[v], neighbourCounts[v], kCancellationRatio).value_or(meshDirection);
        }
    }

    if (stats) *stats = localStats;
    return normals;
}

NormalStats computeVertexNormals(Mesh& mesh, const VertexNormalOptions& options) {
    NormalStats stats;
    mesh.normals = areaWeightedVertexNormals(mesh, options, &stats);
    return stats;
}

std::vector<glm::vec3> faceNormals(const Mesh& mesh, const VertexNormalOptions& options) {
    const std::vector<glm::dvec3> crosses = faceCrossProducts(mesh);
    const glm::vec3 fallback = safeNormalize(options.fallbackNormal, kDefaultFallback);
    std::vector<glm::vec3> normals(crosses.size());
    std::vector<glm::vec3> vertexNormals;  // computed only if a triangle is degenerate
    for (std::size_t t = 0; t < crosses.size(); ++t) {
        if (!isZero(crosses[t])) {
            normals[t] = glm::vec3(glm::normalize(crosses[t]));
            continue;
        }
        if (vertexNormals.empty()) vertexNormals = areaWeightedVertexNormals(mesh, options);
        glm::dvec3 cornerSum(0.0);
        for (int corner = 0; corner < 3; ++corner) cornerSum += glm::dvec3(vertexNormals[mesh.indices[3 * t + corner]]);
        normals[t] = significantDirection(cornerSum, 3.0, kCancellationRatio).value_or(fallback);
    }
    return normals;
}

Mesh makeFlatShaded(const Mesh& mesh, const VertexNormalOptions& options) {
    const std::vector<glm::vec3> perFace = faceNormals(mesh, options);
    const Mesh withoutNormals{mesh.positions, {}, mesh.uvs, mesh.indices};  // old normals may be stale
    Mesh flat = splitVerticesPerFace(withoutNormals);
    flat.normals.resize(flat.positions.size());
    for (std::size_t corner = 0; corner < flat.normals.size(); ++corner) flat.normals[corner] = perFace[corner / 3];
    return flat;
}

}  // namespace prism::geometry
