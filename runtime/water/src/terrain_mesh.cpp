// The terrain mesh and its albedo (see terrain_mesh.hpp).
#include "prism/water/terrain_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace prism::water {
namespace {

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) {
    return a + (b - a) * std::clamp(t, 0.0f, 1.0f);
}

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

std::vector<std::uint32_t> gridIndices(int width, int height) {
    std::vector<std::uint32_t> idx;
    if (width < 2 || height < 2) return idx;
    idx.reserve(static_cast<std::size_t>(width - 1) * (height - 1) * 6);
    const auto v = [&](int x, int z) { return static_cast<std::uint32_t>(z * width + x); };
    for (int z = 0; z + 1 < height; ++z)
        for (int x = 0; x + 1 < width; ++x) {
            idx.insert(idx.end(), {v(x, z), v(x, z + 1), v(x + 1, z)});
            idx.insert(idx.end(), {v(x + 1, z), v(x, z + 1), v(x + 1, z + 1)});
        }
    return idx;
}

TerrainMesh makeTerrainMesh(const HeightField& f, const std::vector<float>& permeability) {
    validate(f, "makeTerrainMesh");
    TerrainMesh t;
    const std::size_t n = f.cellCount();
    t.mesh.positions.resize(n);
    t.mesh.normals.resize(n);
    t.mesh.uvs.resize(n);
    t.colors.resize(n);
    const auto [lowIt, highIt] = std::minmax_element(f.heights.begin(), f.heights.end());
    const float low = *lowIt, range = std::max(1e-6f, *highIt - *lowIt);
    float kMax = 0.0f;
    for (float k : permeability) kMax = std::max(kMax, k);
    const glm::vec3 grass(0.30f, 0.40f, 0.17f), earth(0.42f, 0.33f, 0.22f), rock(0.45f, 0.44f, 0.42f),
        clay(0.50f, 0.45f, 0.38f);
    for (int z = 0; z < f.height; ++z)
        for (int x = 0; x < f.width; ++x) {
            const std::size_t i = f.index(x, z);
            const int xl = std::max(0, x - 1), xr = std::min(f.width - 1, x + 1);
            const int zu = std::max(0, z - 1), zd = std::min(f.height - 1, z + 1);
            const float dx = static_cast<float>(std::max(1, xr - xl)) * f.cellSize;
            const float dz = static_cast<float>(std::max(1, zd - zu)) * f.cellSize;
            glm::vec3 normal(-(f.at(xr, z) - f.at(xl, z)) / dx, 1.0f, -(f.at(x, zd) - f.at(x, zu)) / dz);
            normal /= std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
            t.mesh.positions[i] = {static_cast<float>(x) * f.cellSize, f.heights[i],
                                   static_cast<float>(z) * f.cellSize};
            t.mesh.normals[i] = normal;
            t.mesh.uvs[i] = {(static_cast<float>(x) + 0.5f) / static_cast<float>(f.width),
                             (static_cast<float>(z) + 0.5f) / static_cast<float>(f.height)};
            const float steep = 1.0f - normal.y;  // 0 flat .. 1 vertical
            glm::vec3 albedo = mix(grass, earth, smoothstep(0.02f, 0.10f, steep));
            albedo = mix(albedo, rock, smoothstep(0.15f, 0.35f, steep));
            const float heightShare = (f.heights[i] - low) / range;
            albedo *= 0.85f + 0.3f * heightShare;
            if (!permeability.empty() && kMax > 0.0f) {
                const float compacted = 1.0f - permeability[i] / kMax;
                albedo = mix(albedo, clay, 0.55f * smoothstep(0.6f, 0.95f, compacted));
            }
            t.colors[i] = {albedo, 1.0f};
        }
    t.mesh.indices = gridIndices(f.width, f.height);
    return t;
}

}  // namespace prism::water
