// What mesh data each catalogue shader wants and the meshes the programs offer by name.
//
// Usage (snippet: examples/snippets/render_shader_meshes.cpp):
//
//     #include "prism/render/shader_meshes.hpp"
//     prism::geometry::Mesh m = prism::render::namedMesh("torus", /*subdivision*/ 3);
//     prism::geometry::Mesh ready = prism::render::meshForShader("flat", m);  // split per face, face normals
//
// The flat shader needs face normals on vertices split per face (the NORMAL_FACE
// module of the FUDGE shader thesis's appendix); every other shader gets area-weighted vertex normals (computed when
// the mesh has none). Names: sphere (UV sphere), icosphere, torus, cube, trefoil,
// grid, or a path ending in .obj (loaded and welded, see prism/geometry/obj_loader.hpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "prism/geometry/mesh.hpp"

namespace prism::render {

geometry::Mesh meshForShader(std::string_view shader, const geometry::Mesh& mesh);

// Throws std::invalid_argument listing the known names for an unknown one, and
// geometry::ObjLoadError (file:line) for a bad OBJ file.
geometry::Mesh namedMesh(const std::string& name, unsigned subdivision = 3);
std::vector<std::string> builtInMeshNames();

}  // namespace prism::render
