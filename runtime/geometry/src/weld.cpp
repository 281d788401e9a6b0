// O(n) welding: an open-addressing hash table from exact position (float bit
// patterns, -0.0 folded into 0.0) to the first group at that position; further groups
// at the same position (creases, uv seams) hang off it in a creation-ordered chain.
#include "prism/geometry/weld.hpp"

#include "weld_rules.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace prism::geometry {

namespace {

std::uint32_t canonicalBits(float value) {
    return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value);  // -0.0 hashes like 0.0
}

std::uint64_t hashPosition(const glm::vec3& p) {
    constexpr std::uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;
    std::uint64_t h = canonicalBits(p.x);
    h = (h * kMultiplier) ^ canonicalBits(p.y);
    h = (h * kMultiplier) ^ canonicalBits(p.z);
    // splitmix64 finaliser: spreads nearby bit patterns over the whole table.
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return h;
}

// Open addressing with linear probing. Each slot keeps the position itself next to
// the first group at that position, so a probe touches one cache line; the table
// doubles when half full, so it is sized for the distinct positions, not the input.
class PositionTable {
  public:
    explicit PositionTable(std::size_t expectedPositions) {
        std::size_t capacity = 1024;
        while (capacity < 2 * expectedPositions) capacity *= 2;
        slots_.assign(capacity, Slot{});
    }

    // Asks the CPU to load the slot for `position` early: lookups are random, so
    // overlapping their cache misses is what makes large meshes fast.
    void prefetch(const glm::vec3& position) const {
        __builtin_prefetch(&slots_[hashPosition(position) & (slots_.size() - 1)]);
    }

    // The first group at `position`, or kNoGroup after inserting `newGroup` for it.
    std::uint32_t findOrInsert(const glm::vec3& position, std::uint32_t newGroup) {
        if (2 * (used_ + 1) > slots_.size()) grow();
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = hashPosition(position) & mask;; i = (i + 1) & mask) {
            Slot& slot = slots_[i];
            if (slot.group == detail::kNoGroup) {
                slot = Slot{position, newGroup};
                ++used_;
                return detail::kNoGroup;
            }
            if (detail::samePosition(slot.position, position)) return slot.group;
        }
    }

  private:
    struct Slot {
        glm::vec3 position{0.0f};
        std::uint32_t group = detail::kNoGroup;
    };

    void grow() {
        std::vector<Slot> old(slots_.size() * 2, Slot{});
        old.swap(slots_);
        const std::size_t mask = slots_.size() - 1;
        for (const Slot& slot : old) {
            if (slot.group == detail::kNoGroup) continue;
            std::size_t i = hashPosition(slot.position) & mask;
            while (slots_[i].group != detail::kNoGroup) i = (i + 1) & mask;
            slots_[i] = slot;
        }
    }

    std::vector<Slot> slots_;
    std::size_t used_ = 0;
};

}  // namespace

WeldResult weldVertices(const Mesh& mesh, const WeldOptions& options) {
    const detail::WeldRules rules(mesh, options);
    const std::size_t vertices = mesh.positions.size();
    if (vertices >= detail::kNoGroup) throw std::invalid_argument("weldVertices: too many vertices");

    std::vector<std::uint32_t> groupOfVertex(vertices);
    std::vector<std::uint32_t> firstVertexOfGroup;
    std::vector<std::uint32_t> nextGroupAtSamePosition;
    auto startGroup = [&](std::uint32_t v) {
        const auto group = static_cast<std::uint32_t>(firstVertexOfGroup.size());
        firstVertexOfGroup.push_back(v);
        nextGroupAtSamePosition.push_back(detail::kNoGroup);
        groupOfVertex[v] = group;
        return group;
    };

    // Split meshes (the common input) have about one distinct position per 6 vertices.
    PositionTable table(vertices / 4);
    constexpr std::uint32_t kPrefetchDistance = 16;
    for (std::uint32_t v = 0; v < vertices; ++v) {
        if (v + kPrefetchDistance < vertices) table.prefetch(mesh.positions[v + kPrefetchDistance]);
        const glm::vec3& position = mesh.positions[v];
        if (!detail::isWeldablePosition(position)) {
            startGroup(v);
            continue;
        }
        const auto candidate = static_cast<std::uint32_t>(firstVertexOfGroup.size());
        const std::uint32_t firstGroup = table.findOrInsert(position, candidate);
        if (firstGroup == detail::kNoGroup) {
            startGroup(v);
            continue;
        }
        // Same position: the first group in creation order that accepts v wins.
        std::uint32_t group = firstGroup;
        while (!rules.mayJoin(firstVertexOfGroup[group], v)) {
            if (nextGroupAtSamePosition[group] == detail::kNoGroup) {
                const std::uint32_t added = startGroup(v);
                nextGroupAtSamePosition[group] = added;
                group = added;
                break;
            }
            group = nextGroupAtSamePosition[group];
        }
        groupOfVertex[v] = group;
    }
    return detail::buildWeldResult(mesh, std::move(groupOfVertex), firstVertexOfGroup, options);
}

}  // namespace prism::geometry
