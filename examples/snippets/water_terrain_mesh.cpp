// The usage example of prism/water/terrain_mesh.hpp, compiled and run by tests/snippets.
#include "prism/water/height_field.hpp"
// [snippet]
#include "prism/water/terrain_mesh.hpp"
// [/snippet]

int main() {
    const prism::water::HeightField field = prism::water::proceduralTerrain({.width = 64, .height = 48});
    const std::vector<float> permeability = prism::water::proceduralPermeability(field);
    // [snippet]
    prism::water::TerrainMesh t = prism::water::makeTerrainMesh(field, permeability);
    // t.mesh: positions, normals, uvs, indices; t.colors: one RGBA albedo per vertex
    // [/snippet]
    return t.mesh.positions.size() == 64u * 48u && t.colors.size() == t.mesh.positions.size() ? 0 : 1;
}
