// Terrains and checks shared by the water tests (see water_test_support.hpp).
#include "water_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism::water::test {

HeightField flatTerrain(int width, int height, float level, float cellSize) {
    HeightField f;
    f.width = width;
    f.height = height;
    f.cellSize = cellSize;
    f.heights.assign(f.cellCount(), level);
    return f;
}

HeightField pitTerrain(int size, int pitX, int pitZ, float cellSize) {
    HeightField f = flatTerrain(size, size, 1.0f, cellSize);
    f.heights[f.index(pitX, pitZ)] = 0.0f;
    return f;
}

HeightField cliffTerrain(int size, float step, float cellSize) {
    HeightField f = flatTerrain(size, size, 0.0f, cellSize);
    for (int z = 0; z < size; ++z)
        for (int x = size / 2; x < size; ++x) f.heights[f.index(x, z)] = step;
    return f;
}

HeightField tiltedTerrain(int size, float slope, float cellSize) {
    HeightField f = flatTerrain(size, size, 0.0f, cellSize);
    for (int z = 0; z < size; ++z)
        for (int x = 0; x < size; ++x) f.heights[f.index(x, z)] = -slope * cellSize * static_cast<float>(x);
    return f;
}

HeightField bowlTerrain(int size, float depth, float cellSize) {
    HeightField f = flatTerrain(size, size, 0.0f, cellSize);
    const float c = 0.5f * static_cast<float>(size - 1);
    for (int z = 0; z < size; ++z)
        for (int x = 0; x < size; ++x) {
            const float dx = (static_cast<float>(x) - c) / c, dz = (static_cast<float>(z) - c) / c;
            f.heights[f.index(x, z)] = depth * std::min(1.0f, 0.5f * (dx * dx + dz * dz));
        }
    return f;
}

WaterStats statsOf(const std::vector<float>& depth) {
    WaterStats s;
    s.minDepth = std::numeric_limits<float>::infinity();
    s.maxDepth = -std::numeric_limits<float>::infinity();
    for (float d : depth) {
        if (!std::isfinite(d)) {
            ++s.nonFinite;
            continue;
        }
        if (d < 0.0f) ++s.negative;
        s.minDepth = std::min(s.minDepth, d);
        s.maxDepth = std::max(s.maxDepth, d);
        s.sum += d;
    }
    return s;
}

void expectFiniteNonNegative(const WaterSimulation& sim, const std::string& what) {
    const WaterStats s = statsOf(sim.depth());
    EXPECT_EQ(s.nonFinite, 0u) << what << ": NaN or infinite depths";
    EXPECT_EQ(s.negative, 0u) << what << ": negative depths (min " << s.minDepth << " m)";
    for (const glm::vec2& q : sim.edgeVelocities())
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
            ADD_FAILURE() << what << ": NaN or infinite edge velocity";
            break;
        }
}

std::filesystem::path scratchDir(const std::string& name) {
#ifdef PRISM_WATER_TEST_TEMP_DIR
    const std::filesystem::path base = PRISM_WATER_TEST_TEMP_DIR;
#else
    const std::filesystem::path base = std::filesystem::temp_directory_path() / "prism-water-tests";
#endif
    const std::filesystem::path dir = base / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace prism::water::test
