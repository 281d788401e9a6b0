// Mesh preparation per shader and the named meshes (see prism/render/shader_meshes.hpp).
#include "prism/render/shader_meshes.hpp"

#include <algorithm>
#include <stdexcept>

#include "prism/geometry/normals.hpp"
#include "prism/geometry/obj_loader.hpp"
#include "prism/geometry/procedural_meshes.hpp"

namespace prism::render {

geometry::Mesh meshForShader(std::string_view shader, const geometry::Mesh& mesh) {
    if (shader == "flat") return geometry::makeFlatShaded(mesh);
    geometry::Mesh out = mesh;
    if (out.normals.size() != out.positions.size()) geometry::computeVertexNormals(out);
    return out;
}

std::vector<std::string> builtInMeshNames() {
    return {"sphere", "icosphere", "torus", "cube", "trefoil", "grid"};
}

geometry::Mesh namedMesh(const std::string& name, unsigned subdivision) {
    const unsigned s = std::clamp(subdivision, 0u, 7u);
    if (name == "sphere") return geometry::makeUvSphere(1.0f, 4u << s, 8u << s);
    if (name == "icosphere") return geometry::makeIcosphere(1.0f, s);
    if (name == "torus") return geometry::makeTorus(0.8f, 0.3f, 12u << s, 6u << s);
    if (name == "cube") return geometry::makeCube(1.4f);
    if (name == "trefoil") return geometry::makeTrefoilKnot();
    if (name == "grid") return geometry::makeGrid(2.0f, 2.0f, 2u << s, 2u << s);
    if (name.size() > 4 && name.substr(name.size() - 4) == ".obj") {
        geometry::ObjLoadOptions options;
        options.weld = true;
        options.creaseAngleDegrees = 60.0f;  // smooth surfaces, sharp edges stay sharp
        return geometry::loadObj(name, options);
    }
    std::string known;
    for (const auto& n : builtInMeshNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown mesh '" + name + "'; use one of " + known + " or a path to an .obj file");
}

}  // namespace prism::render
