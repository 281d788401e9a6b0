// Internal: whether a point has no NaN or infinite coordinate, the one test the mesh
// helpers and the normals share (they skip or replace such points). Not installed.
#pragma once

#include <glm/vec3.hpp>

#include <cmath>

namespace prism::geometry::detail {

inline bool isFinite(const glm::vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace prism::geometry::detail
