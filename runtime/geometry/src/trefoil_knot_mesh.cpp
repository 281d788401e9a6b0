// makeTrefoilKnot: the gallery's showcase mesh, a rope-like ribbed tube along a
// trefoil knot. The tube's cross-section frame is parallel-transported along the
// curve (no Frenet flips) and its leftover twist after one loop is spread evenly, so
// the surface closes without a seam. Normals are the mesh's own area-weighted ones.
#include "prism/geometry/procedural_meshes.hpp"

#include "prism/geometry/normals.hpp"
#include "shape_parameter_checks.hpp"

#include <glm/ext/scalar_constants.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace prism::geometry {

namespace {

// The trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) scaled by 1/3 so that it
// fits in the unit sphere; strands stay >= 0.40 apart and bends have radius >= 0.42.
glm::dvec3 knotPoint(double t) {
    return glm::dvec3(std::sin(t) + 2.0 * std::sin(2.0 * t), std::cos(t) - 2.0 * std::cos(2.0 * t),
                      -std::sin(3.0 * t)) /
           3.0;
}

glm::dvec3 knotTangent(double t) {
    return glm::normalize(glm::dvec3(std::cos(t) + 4.0 * std::cos(2.0 * t), -std::sin(t) + 4.0 * std::sin(2.0 * t),
                                     -3.0 * std::cos(3.0 * t)));
}

// Removes the tangent component of `v` and normalises.
glm::dvec3 perpendicularPart(const glm::dvec3& v, const glm::dvec3& tangent) {
    return glm::normalize(v - glm::dot(v, tangent) * tangent);
}

// Rotates `v` (perpendicular to `axis`) by `angle` around the unit `axis`.
glm::dvec3 rotateAround(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    return std::cos(angle) * v + std::sin(angle) * glm::cross(axis, v);
}

struct TubeFrame {
    glm::dvec3 centre, tangent, normal, binormal;
};

std::vector<TubeFrame> transportedFrames(std::uint32_t pathSegments) {
    const double pi = glm::pi<double>();
    std::vector<TubeFrame> frames(pathSegments);
    for (std::uint32_t i = 0; i < pathSegments; ++i) {
        const double t = 2.0 * pi * i / pathSegments;
        frames[i].centre = knotPoint(t);
        frames[i].tangent = knotTangent(t);
    }
    // Start with any normal, then carry it along by projection (small steps).
    const glm::dvec3 t0 = frames[0].tangent;
    const glm::dvec3 seed = std::abs(t0.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    frames[0].normal = perpendicularPart(seed, t0);
    for (std::uint32_t i = 1; i < pathSegments; ++i)
        frames[i].normal = perpendicularPart(frames[i - 1].normal, frames[i].tangent);
    // After a full loop the frame comes back rotated by `holonomy`: undo it gradually.
    const glm::dvec3 returned = perpendicularPart(frames[pathSegments - 1].normal, t0);
    const double holonomy =
        std::atan2(glm::dot(glm::cross(returned, frames[0].normal), t0), glm::dot(returned, frames[0].normal));
    for (std::uint32_t i = 0; i < pathSegments; ++i) {
        TubeFrame& frame = frames[i];
        frame.normal = rotateAround(frame.normal, frame.tangent, holonomy * i / pathSegments);
        frame.binormal = glm::cross(frame.tangent, frame.normal);
    }
    return frames;
}

}  // namespace

Mesh makeTrefoilKnot(const TrefoilKnotShape& shape) {
    constexpr const char* kName = "makeTrefoilKnot";
    detail::requireCountInRange(kName, "pathSegments", shape.pathSegments, 24, 4 * detail::kMaxSegments);
    detail::requireCountInRange(kName, "tubeSegments", shape.tubeSegments, 3, detail::kMaxSegments);
    detail::requirePositiveSize(kName, "tubeRadius", shape.tubeRadius);
    detail::requireInRange(kName, "tubeRadius", shape.tubeRadius, 0.0f, 0.15f);
    detail::requireCountInRange(kName, "ridges", shape.ridges, 0, 64);
    detail::requireInRange(kName, "ridgeDepth", shape.ridgeDepth, 0.0f, 0.25f);
    detail::requireCountInRange(kName, "ridgeTwists", shape.ridgeTwists, 0, 64);

    const double pi = glm::pi<double>();
    const std::uint32_t path = shape.pathSegments, tube = shape.tubeSegments;
    const std::vector<TubeFrame> frames = transportedFrames(path);

    Mesh mesh;
    mesh.positions.reserve(std::size_t(path) * tube);
    for (std::uint32_t i = 0; i < path; ++i) {
        const TubeFrame& frame = frames[i];
        const double alongKnot = 2.0 * pi * i / path;
        for (std::uint32_t j = 0; j < tube; ++j) {
            const double aroundTube = 2.0 * pi * j / tube;
            // Grooves: the radius follows a cosine around the tube that turns
            // ridgeTwists times along the knot (integer, so the pattern closes).
            const double groove = std::cos(shape.ridges * aroundTube + shape.ridgeTwists * alongKnot);
            const double radius = shape.tubeRadius * (1.0 + shape.ridgeDepth * groove);
            const glm::dvec3 radial = std::cos(aroundTube) * frame.normal + std::sin(aroundTube) * frame.binormal;
            mesh.positions.push_back(glm::vec3(frame.centre + radius * radial));
        }
    }
    // Around the tube first, then along the knot, winds CCW seen from outside; the
    // indices wrap in both directions, so the surface is closed and seamless.
    auto vertex = [&](std::uint32_t i, std::uint32_t j) { return (i % path) * tube + (j % tube); };
    mesh.indices.reserve(std::size_t(path) * tube * 6);
    for (std::uint32_t i = 0; i < path; ++i) {
        for (std::uint32_t j = 0; j < tube; ++j) {
            const std::uint32_t a = vertex(i, j), b = vertex(i, j + 1), c = vertex(i + 1, j), d = vertex(i + 1, j + 1);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    }
    computeVertexNormals(mesh);
    return mesh;
}

}  // namespace prism::geometry
