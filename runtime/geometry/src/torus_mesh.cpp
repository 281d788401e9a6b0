// makeTorus: a ring around the Y axis with a circular tube, uv seams duplicated.
#include "prism/geometry/procedural_meshes.hpp"

#include "shape_parameter_checks.hpp"

#include <glm/ext/scalar_constants.hpp>

#include <cmath>
#include <stdexcept>

namespace prism::geometry {

Mesh makeTorus(float majorRadius, float minorRadius, std::uint32_t majorSegments, std::uint32_t minorSegments) {
    detail::requirePositiveSize("makeTorus", "majorRadius", majorRadius);
    detail::requirePositiveSize("makeTorus", "minorRadius", minorRadius);
    if (!(minorRadius < majorRadius))
        throw std::invalid_argument(
            "makeTorus: minorRadius must be smaller than majorRadius (the tube would "
            "intersect itself)");
    detail::requireCountInRange("makeTorus", "majorSegments", majorSegments, 3, detail::kMaxSegments);
    detail::requireCountInRange("makeTorus", "minorSegments", minorSegments, 3, detail::kMaxSegments);
    const double pi = glm::pi<double>();

    Mesh mesh;
    for (std::uint32_t i = 0; i <= majorSegments; ++i) {
        const double around = 2.0 * pi * (i % majorSegments) / majorSegments;  // along the ring; seam exact
        const glm::dvec3 outward(std::cos(around), 0.0, std::sin(around));
        for (std::uint32_t j = 0; j <= minorSegments; ++j) {
            const double tube = 2.0 * pi * (j % minorSegments) / minorSegments;  // around the tube
            const glm::dvec3 normal = std::cos(tube) * outward + glm::dvec3(0.0, std::sin(tube), 0.0);
            mesh.positions.push_back(
                glm::vec3(static_cast<double>(majorRadius) * outward + static_cast<double>(minorRadius) * normal));
            mesh.normals.push_back(glm::vec3(normal));
            mesh.uvs.push_back({static_cast<float>(i) / static_cast<float>(majorSegments),
                                static_cast<float>(j) / static_cast<float>(minorSegments)});
        }
    }
    // Around the tube first, then along the ring, winds CCW seen from outside.
    auto vertex = [&](std::uint32_t i, std::uint32_t j) { return i * (minorSegments + 1) + j; };
    for (std::uint32_t i = 0; i < majorSegments; ++i) {
        for (std::uint32_t j = 0; j < minorSegments; ++j) {
            const std::uint32_t a = vertex(i, j), b = vertex(i, j + 1), c = vertex(i + 1, j), d = vertex(i + 1, j + 1);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    }
    return mesh;
}

}  // namespace prism::geometry
