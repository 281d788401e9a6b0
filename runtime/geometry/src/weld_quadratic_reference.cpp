// The FUDGE shader thesis's way to find shared vertices (createVertexNormals() for
// imported meshes, §6.3): compare every vertex's position against the others. O(n^2);
// kept as the reference for cross-checks and the benchmark. Same rules and result as
// weldVertices.
#include "prism/geometry/weld.hpp"

#include "weld_rules.hpp"

#include <stdexcept>

namespace prism::geometry {

WeldResult weldQuadraticReference(const Mesh& mesh, const WeldOptions& options) {
    const detail::WeldRules rules(mesh, options);
    const std::size_t vertices = mesh.positions.size();
    if (vertices >= detail::kNoGroup) throw std::invalid_argument("weldQuadraticReference: too many vertices");

    std::vector<std::uint32_t> groupOfVertex(vertices);
    std::vector<std::uint32_t> firstVertexOfGroup;
    std::vector<bool> startsGroup(vertices, false);
    for (std::uint32_t v = 0; v < vertices; ++v) {
        std::uint32_t group = detail::kNoGroup;
        if (detail::isWeldablePosition(mesh.positions[v])) {
            // Earlier group starters in increasing order = groups in creation order.
            for (std::uint32_t other = 0; other < v; ++other) {
                if (startsGroup[other] && detail::samePosition(mesh.positions[other], mesh.positions[v]) &&
                    rules.mayJoin(other, v)) {
                    group = groupOfVertex[other];
                    break;
                }
            }
        }
        if (group == detail::kNoGroup) {
            group = static_cast<std::uint32_t>(firstVertexOfGroup.size());
            firstVertexOfGroup.push_back(v);
            startsGroup[v] = true;
        }
        groupOfVertex[v] = group;
    }
    return detail::buildWeldResult(mesh, std::move(groupOfVertex), firstVertexOfGroup, options);
}

}  // namespace prism::geometry
