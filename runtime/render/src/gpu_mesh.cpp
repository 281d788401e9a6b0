// Vertex buffers for a Mesh (see prism/render/gpu_mesh.hpp).
#include "prism/render/gpu_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "prism/gl/gl.hpp"

namespace prism::render {
namespace {

gl::Buffer uploadVec3(const std::vector<glm::vec3>& data, int location) {
    gl::Buffer buffer = gl::Buffer::create();
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec3)), data.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    glVertexAttribPointer(static_cast<GLuint>(location), 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    return buffer;
}

}  // namespace

GpuMesh::GpuMesh(const geometry::Mesh& mesh, std::span<const catalog::Attribute> contract) {
    geometry::requireValidMesh(mesh, "GpuMesh");
    vao_ = gl::VertexArray::create();
    glBindVertexArray(vao_.id());
    const int positionLocation = catalog::attributeLocation(contract, "a_position");
    const int normalLocation = catalog::attributeLocation(contract, "a_normal");
    attributes_ = {{"a_position", positionLocation}, {"a_normal", normalLocation}};
    positions_ = uploadVec3(mesh.positions, positionLocation);
    if (!mesh.normals.empty()) {
        normals_ = uploadVec3(mesh.normals, normalLocation);
    } else {
        glDisableVertexAttribArray(static_cast<GLuint>(normalLocation));
        glVertexAttrib3f(static_cast<GLuint>(normalLocation), 0.0f, 0.0f, 1.0f);
    }
    indices_ = gl::Buffer::create();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    indexCount_ = mesh.indices.size();
    glBindVertexArray(0);
    gl::throwIfGlError("uploading a mesh");
}

void GpuMesh::requireAttributesOf(const gl::Program& program) const {
    std::vector<std::string> fed;
    for (const auto& a : attributes_) fed.push_back(a.name);
    for (const auto& wanted : program.activeAttributes()) {
        const auto it = std::find_if(attributes_.begin(), attributes_.end(),
                                     [&](const gl::AttributeBinding& a) { return a.name == wanted.name; });
        const std::string who = "program '" + program.label() + "' reads vertex attribute '" + wanted.name + "'";
        if (it == attributes_.end())
            throw MeshAttributeError(who + ", which the mesh does not provide" + catalog::didYouMean(wanted.name, fed) +
                                     "; the mesh provides " + catalog::nameList(fed) +
                                     ": fix the name in the shader, or feed it with a vertex array of your own");
        if (it->location != wanted.location)
            throw MeshAttributeError(who + " at location " + std::to_string(wanted.location) +
                                     ", but the mesh feeds it at location " + std::to_string(it->location) +
                                     "; build the program and the mesh with the same contract attributes");
    }
}

void GpuMesh::draw(const gl::Program& program) const {
    requireAttributesOf(program);
    program.reportUnsetUniforms();
    draw();
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace prism::render
