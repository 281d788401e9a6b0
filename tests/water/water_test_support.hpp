// Shared pieces of the water tests: small terrains with known features (flat, a single
// pit, a cliff, a tilted plane, a bowl), checks that a water map is finite and
// non-negative, and a scratch directory.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "prism/water/height_field.hpp"
#include "prism/water/water_simulation.hpp"

namespace prism::water::test {

HeightField flatTerrain(int width, int height, float level = 0.0f, float cellSize = 0.25f);
// Flat at 1 m with one cell (x, z) lowered to 0.
HeightField pitTerrain(int size, int pitX, int pitZ, float cellSize = 0.25f);
// x < size / 2 at `low`, the rest `step` metres higher.
HeightField cliffTerrain(int size, float step, float cellSize = 0.25f);
// Falls by `slope` metres per metre towards +x.
HeightField tiltedTerrain(int size, float slope, float cellSize = 0.25f);
// A paraboloid bowl, lowest in the middle, rim `depth` metres higher.
HeightField bowlTerrain(int size, float depth, float cellSize = 0.25f);

struct WaterStats {
    std::size_t nonFinite = 0;
    std::size_t negative = 0;
    float minDepth = 0.0f, maxDepth = 0.0f;
    double sum = 0.0;
};
WaterStats statsOf(const std::vector<float>& depth);

// EXPECTs no NaN/Inf and no negative depth; `what` names the case in the message.
void expectFiniteNonNegative(const WaterSimulation& sim, const std::string& what);

// A fresh directory below the build tree for files a test writes.
std::filesystem::path scratchDir(const std::string& name);

}  // namespace prism::water::test
