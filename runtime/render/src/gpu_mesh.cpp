// Vertex buffers for a Mesh (see prism/render/gpu_mesh.hpp).
#include "prism/render/gpu_mesh.hpp"

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
    positions_ = uploadVec3(mesh.positions, catalog::attributeLocation(contract, "a_position"));
    const int normalLocation = catalog::attributeLocation(contract, "a_normal");
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

void GpuMesh::draw() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace prism::render
