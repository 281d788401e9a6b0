// makeGrid: a flat, subdivided plane in XZ facing +Y (a floor or a terrain base).
#include "prism/geometry/procedural_meshes.hpp"

#include "shape_parameter_checks.hpp"

namespace prism::geometry {

Mesh makeGrid(float width, float depth, std::uint32_t columns, std::uint32_t rows) {
    detail::requirePositiveSize("makeGrid", "width", width);
    detail::requirePositiveSize("makeGrid", "depth", depth);
    detail::requireCountInRange("makeGrid", "columns", columns, 1, detail::kMaxSegments);
    detail::requireCountInRange("makeGrid", "rows", rows, 1, detail::kMaxSegments);

    Mesh mesh;
    for (std::uint32_t i = 0; i <= columns; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(columns);
        for (std::uint32_t k = 0; k <= rows; ++k) {
            const float v = static_cast<float>(k) / static_cast<float>(rows);
            mesh.positions.push_back({(u - 0.5f) * width, 0.0f, (v - 0.5f) * depth});
            mesh.normals.push_back({0.0f, 1.0f, 0.0f});
            mesh.uvs.push_back({u, 1.0f - v});
        }
    }
    // +Z then +X winds CCW seen from +Y.
    auto vertex = [&](std::uint32_t i, std::uint32_t k) { return i * (rows + 1) + k; };
    for (std::uint32_t i = 0; i < columns; ++i) {
        for (std::uint32_t k = 0; k < rows; ++k) {
            const std::uint32_t a = vertex(i, k), b = vertex(i, k + 1), c = vertex(i + 1, k), d = vertex(i + 1, k + 1);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    }
    return mesh;
}

}  // namespace prism::geometry
