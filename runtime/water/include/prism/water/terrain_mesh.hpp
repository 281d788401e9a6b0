// The terrain as a mesh: one vertex per height-field cell at (x h, height, z h), normals
// from central differences, the cell centre as texture coordinate, and an albedo per
// vertex coloured by slope (grass on the flat, earth on slopes, rock on steep ground),
// height and permeability (compacted ground is greyer).
//
// Usage (snippet: examples/snippets/water_terrain_mesh.cpp):
//
//     #include "prism/water/terrain_mesh.hpp"
//     prism::water::TerrainMesh t = prism::water::makeTerrainMesh(field, permeability);
//     // t.mesh: positions, normals, uvs, indices; t.colors: one RGBA albedo per vertex
#pragma once

#include <glm/vec4.hpp>

#include <vector>

#include "prism/geometry/mesh.hpp"
#include "prism/water/height_field.hpp"

namespace prism::water {

struct TerrainMesh {
    geometry::Mesh mesh;
    std::vector<glm::vec4> colors;
};

// `permeability` may be empty (no soil tint); otherwise one value per cell (m/s).
TerrainMesh makeTerrainMesh(const HeightField& field, const std::vector<float>& permeability);

// Triangle-list indices over a width x height vertex grid (two triangles per cell,
// counter-clockwise seen from +y).
std::vector<std::uint32_t> gridIndices(int width, int height);

}  // namespace prism::water
