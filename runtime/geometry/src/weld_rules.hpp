// Internal: the rules both welding methods share (when two vertices may merge) and
// how a grouping of vertices becomes the welded mesh. Not installed.
#pragma once

#include "prism/geometry/weld.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace prism::geometry::detail {

inline constexpr std::uint32_t kNoGroup = 0xFFFFFFFFu;

inline bool isWeldablePosition(const glm::vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Exact float comparison: -0.0 == 0.0; positions with NaN/Inf are excluded earlier.
inline bool samePosition(const glm::vec3& a, const glm::vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

class WeldRules {
  public:
    // Validates the mesh and the crease angle (std::invalid_argument).
    WeldRules(const Mesh& mesh, const WeldOptions& options);

    // Whether vertex `candidate` (at the same position) may join the group started
    // by vertex `groupFirst`: equal uvs when seams are kept, directions within the
    // crease angle when one is set.
    bool mayJoin(std::uint32_t groupFirst, std::uint32_t candidate) const;

  private:
    const Mesh& mesh_;
    bool compareUvs_ = false;
    bool useCrease_ = false;
    float minimumCosine_ = -1.0f;
    std::vector<glm::vec3> directions_;  // unit, or zero when a vertex has none
};

// Builds the welded mesh from the group of every input vertex and the first vertex of
// every group (groups numbered in creation order).
WeldResult buildWeldResult(const Mesh& mesh, std::vector<std::uint32_t> groupOfVertex,
                           const std::vector<std::uint32_t>& firstVertexOfGroup, const WeldOptions& options);

}  // namespace prism::geometry::detail
