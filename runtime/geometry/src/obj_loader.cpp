// loadObj: reads the file, pre-validates it (file:line errors), lets tinyobjloader
// parse and triangulate it, and turns the result into a split-per-face Mesh.
#include "prism/geometry/obj_loader.hpp"

#include "obj_validation.hpp"
#include "prism/geometry/normals.hpp"
#include "prism/geometry/weld.hpp"

#include <tiny_obj_loader.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace prism::geometry {

namespace {

std::string formatLocation(const std::filesystem::path& file, std::size_t line) {
    return line > 0 ? file.string() + ":" + std::to_string(line) : file.string();
}

std::string readWholeFile(const std::filesystem::path& file) {
    std::error_code error;
    if (std::filesystem::is_directory(file, error))
        throw ObjLoadError(file, 0, "cannot read the file: it is a directory; pass the path of an .obj file");
    std::ifstream stream(file, std::ios::binary);
    if (!stream) {
        const int code = errno;
        throw ObjLoadError(file, 0,
                           std::string("cannot open the file (") + (code ? std::strerror(code) : "unknown reason") +
                               "); check that the path is right and the file is readable");
    }
    std::ostringstream contents;
    contents << stream.rdbuf();
    if (stream.bad()) throw ObjLoadError(file, 0, "reading the file failed part-way; check the disk and try again");
    return contents.str();
}

// tinyobjloader sometimes mentions "line N" in its messages: use it if present.
std::size_t lineMentionedIn(const std::string& message) {
    const std::size_t at = message.find("line ");
    if (at == std::string::npos) return 0;
    std::size_t line = 0, i = at + 5;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])))
        line = line * 10 + static_cast<std::size_t>(message[i++] - '0');
    return line;
}

std::string firstLineOf(const std::string& message) {
    std::string first = message.substr(0, message.find('\n'));
    return first.empty() ? "tinyobjloader could not parse the file" : first;
}

// Element `index` of a packed xyz array; the pre-validation makes a bad index
// impossible, this check only guards against a parser surprise.
glm::vec3 attribute3(const std::vector<tinyobj::real_t>& values, int index, const std::filesystem::path& file) {
    const auto i = static_cast<std::size_t>(index) * 3;
    if (index < 0 || i + 2 >= values.size())
        throw ObjLoadError(file, 0, "tinyobjloader returned an index out of range; the file is probably malformed");
    return {values[i], values[i + 1], values[i + 2]};
}

}  // namespace

ObjLoadError::ObjLoadError(std::filesystem::path file, std::size_t line, const std::string& message)
    : std::runtime_error(formatLocation(file, line) + ": error: " + message), file_(std::move(file)), line_(line) {}

Mesh loadObj(const std::filesystem::path& file, const ObjLoadOptions& options) {
    const std::string text = readWholeFile(file);
    if (auto problem = detail::findFirstObjProblem(text)) throw ObjLoadError(file, problem->line, problem->message);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config) || !reader.Valid())
        throw ObjLoadError(file, lineMentionedIn(reader.Error()), firstLineOf(reader.Error()));

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    Mesh mesh;
    bool everyCornerHasNormal = true, everyCornerHasUv = true;
    std::vector<glm::vec3> fileNormals;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& faces = shape.mesh;
        std::size_t corner = 0;
        for (const unsigned char cornersInFace : faces.num_face_vertices) {
            if (cornersInFace != 3) {  // cannot happen with triangulate; skip rather than misread
                corner += cornersInFace;
                continue;
            }
            for (int k = 0; k < 3; ++k, ++corner) {
                const tinyobj::index_t& index = faces.indices[corner];
                mesh.positions.push_back(attribute3(attrib.vertices, index.vertex_index, file));
                if (index.normal_index >= 0)
                    fileNormals.push_back(attribute3(attrib.normals, index.normal_index, file));
                else
                    everyCornerHasNormal = false;
                if (index.texcoord_index >= 0) {
                    const auto t = static_cast<std::size_t>(index.texcoord_index) * 2;
                    if (t + 1 >= attrib.texcoords.size())
                        throw ObjLoadError(file, 0, "tinyobjloader returned a texture coordinate index out of range");
                    mesh.uvs.push_back({attrib.texcoords[t], attrib.texcoords[t + 1]});
                } else {
                    everyCornerHasUv = false;
                }
                mesh.indices.push_back(static_cast<std::uint32_t>(mesh.indices.size()));
            }
        }
    }
    if (mesh.indices.empty())
        throw ObjLoadError(file, 0, "the file contains no faces (`f` lines), so there is no mesh to load");
    if (!everyCornerHasUv) mesh.uvs.clear();

    if (options.weld) {
        WeldOptions weld;
        weld.creaseAngleDegrees = options.creaseAngleDegrees;
        return weldVertices(mesh, weld).mesh;
    }
    // Split per face, so area-weighted normals are the face normals.
    computeVertexNormals(mesh);
    if (options.useFileNormals && everyCornerHasNormal) {
        // The file's normals, normalised; a zero or broken one keeps the face normal.
        for (std::size_t i = 0; i < mesh.normals.size(); ++i)
            mesh.normals[i] = safeNormalize(fileNormals[i], mesh.normals[i]);
    }
    return mesh;
}

}  // namespace prism::geometry
