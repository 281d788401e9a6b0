// makeCube: 6 faces with 4 vertices each, so that every face is flat shaded.
#include "prism/geometry/procedural_meshes.hpp"

#include "shape_parameter_checks.hpp"

namespace prism::geometry {

namespace {

struct CubeFace {
    glm::vec3 normal;
    glm::vec3 right;  // right x up == normal, so corners listed as below run CCW
    glm::vec3 up;
};

constexpr CubeFace kCubeFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
};

}  // namespace

Mesh makeCube(float edgeLength) {
    detail::requirePositiveSize("makeCube", "edgeLength", edgeLength);
    const float half = 0.5f * edgeLength;
    constexpr glm::vec2 kCornerSigns[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

    Mesh mesh;
    mesh.positions.reserve(24);
    mesh.normals.reserve(24);
    mesh.uvs.reserve(24);
    mesh.indices.reserve(36);
    for (const CubeFace& face : kCubeFaces) {
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec2& sign : kCornerSigns) {
            mesh.positions.push_back(half * (face.normal + sign.x * face.right + sign.y * face.up));
            mesh.normals.push_back(face.normal);
            mesh.uvs.push_back(0.5f * (sign + 1.0f));
        }
        for (std::uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + corner);
    }
    return mesh;
}

}  // namespace prism::geometry
