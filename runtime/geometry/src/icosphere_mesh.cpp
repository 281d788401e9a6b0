// makeIcosphere: an icosahedron whose triangles are split into four, `level` times,
// with new vertices pushed onto the sphere. Each edge midpoint is created once (edge
// cache), so every vertex is shared: V = 10 * 4^level + 2, F = 20 * 4^level.
#include "prism/geometry/procedural_meshes.hpp"

#include "shape_parameter_checks.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <unordered_map>

namespace prism::geometry {

namespace {

constexpr std::uint32_t kMaxIcosphereLevel = 7;

// The 12 corners of an icosahedron, (0, +-1, +-phi) and its cyclic permutations.
std::vector<glm::dvec3> icosahedronCorners() {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    return {{-1, phi, 0},  {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi},  {0, 1, phi},
            {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1},  {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
}

// Its 20 faces, counter-clockwise seen from outside.
constexpr std::uint32_t kIcosahedronFaces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

class MidpointCache {
  public:
    explicit MidpointCache(std::vector<glm::dvec3>& directions) : directions_(directions) {}

    // The vertex halfway along edge (a, b) on the unit sphere, created on first use.
    std::uint32_t midpoint(std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
        auto [it, inserted] = cache_.try_emplace(key, static_cast<std::uint32_t>(directions_.size()));
        if (inserted) directions_.push_back(glm::normalize(directions_[a] + directions_[b]));
        return it->second;
    }

  private:
    std::vector<glm::dvec3>& directions_;
    std::unordered_map<std::uint64_t, std::uint32_t> cache_;
};

}  // namespace

std::uint32_t icosphereVertexCount(std::uint32_t level) {
    return 10u * (1u << (2u * level)) + 2u;
}

Mesh makeIcosphere(float radius, std::uint32_t level) {
    detail::requirePositiveSize("makeIcosphere", "radius", radius);
    detail::requireCountInRange("makeIcosphere", "level", level, 0, kMaxIcosphereLevel);

    std::vector<glm::dvec3> directions;
    directions.reserve(icosphereVertexCount(level));
    for (const glm::dvec3& corner : icosahedronCorners()) directions.push_back(glm::normalize(corner));
    std::vector<std::uint32_t> indices(&kIcosahedronFaces[0][0], &kIcosahedronFaces[0][0] + 60);

    for (std::uint32_t step = 0; step < level; ++step) {
        MidpointCache cache(directions);
        std::vector<std::uint32_t> finer;
        finer.reserve(indices.size() * 4);
        for (std::size_t t = 0; t < indices.size(); t += 3) {
            const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
            const std::uint32_t ab = cache.midpoint(a, b), bc = cache.midpoint(b, c), ca = cache.midpoint(c, a);
            // Four children with the parent's orientation.
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        indices = std::move(finer);
    }

    Mesh mesh;
    mesh.positions.reserve(directions.size());
    mesh.normals.reserve(directions.size());
    for (const glm::dvec3& direction : directions) {
        mesh.normals.push_back(glm::vec3(direction));
        mesh.positions.push_back(glm::vec3(direction * static_cast<double>(radius)));
    }
    mesh.indices = std::move(indices);
    return mesh;
}

}  // namespace prism::geometry
