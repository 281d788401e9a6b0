// makeUvSphere: latitude/longitude sphere with one pole vertex per segment and a
// duplicated seam column, so that uvs are continuous and every vertex is used.
#include "prism/geometry/procedural_meshes.hpp"

#include "shape_parameter_checks.hpp"

#include <glm/ext/scalar_constants.hpp>

#include <cmath>

namespace prism::geometry {

Mesh makeUvSphere(float radius, std::uint32_t rings, std::uint32_t segments) {
    detail::requirePositiveSize("makeUvSphere", "radius", radius);
    detail::requireCountInRange("makeUvSphere", "rings", rings, 2, detail::kMaxSegments);
    detail::requireCountInRange("makeUvSphere", "segments", segments, 3, detail::kMaxSegments);
    const double pi = glm::pi<double>();

    Mesh mesh;
    auto addVertex = [&](double polar, double azimuth, glm::vec2 uv) {
        // Polar angle from +Y; azimuth from +X towards +Z.
        const bool pole = polar == 0.0 || polar == pi;  // exactly (0, +-1, 0), no sin(pi) residue
        const double ringRadius = pole ? 0.0 : std::sin(polar);
        const glm::dvec3 direction(ringRadius * std::cos(azimuth), polar == pi ? -1.0 : std::cos(polar),
                                   ringRadius * std::sin(azimuth));
        mesh.normals.push_back(glm::vec3(direction));
        mesh.positions.push_back(glm::vec3(direction * static_cast<double>(radius)));
        mesh.uvs.push_back(uv);
    };

    // Top pole: one vertex per segment, at the middle of the segment in u.
    for (std::uint32_t s = 0; s < segments; ++s)
        addVertex(0.0, 0.0, {(static_cast<float>(s) + 0.5f) / static_cast<float>(segments), 1.0f});
    // Inner rings 1..rings-1, seam column duplicated (s == segments).
    for (std::uint32_t r = 1; r < rings; ++r) {
        const double polar = pi * r / rings;
        for (std::uint32_t s = 0; s <= segments; ++s)
            addVertex(polar, 2.0 * pi * (s % segments) / segments,  // seam exactly on s == 0
                      {static_cast<float>(s) / static_cast<float>(segments),
                       1.0f - static_cast<float>(r) / static_cast<float>(rings)});
    }
    const auto bottomPole = static_cast<std::uint32_t>(mesh.positions.size());
    for (std::uint32_t s = 0; s < segments; ++s)
        addVertex(pi, 0.0, {(static_cast<float>(s) + 0.5f) / static_cast<float>(segments), 0.0f});

    // Going along increasing azimuth, then towards the south, winds CCW seen from outside.
    auto ringVertex = [&](std::uint32_t r, std::uint32_t s) { return segments + (r - 1) * (segments + 1) + s; };
    for (std::uint32_t s = 0; s < segments; ++s)
        mesh.indices.insert(mesh.indices.end(), {s, ringVertex(1, s + 1), ringVertex(1, s)});
    for (std::uint32_t r = 1; r + 1 < rings; ++r) {
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint32_t a = ringVertex(r, s), b = ringVertex(r, s + 1);
            const std::uint32_t c = ringVertex(r + 1, s), d = ringVertex(r + 1, s + 1);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    }
    for (std::uint32_t s = 0; s < segments; ++s)
        mesh.indices.insert(mesh.indices.end(),
                            {ringVertex(rings - 1, s), ringVertex(rings - 1, s + 1), bottomPole + s});
    return mesh;
}

}  // namespace prism::geometry
