// Vertex buffers for a Mesh (see prism/render/gpu_mesh.hpp).
#include "prism/render/gpu_mesh.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "prism/gl/gl.hpp"

namespace prism::render {
namespace {

unsigned uploadVec3(const std::vector<glm::vec3>& data, int location) {
    unsigned buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec3)), data.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    glVertexAttribPointer(static_cast<GLuint>(location), 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    return buffer;
}

}  // namespace

GpuMesh::GpuMesh(const geometry::Mesh& mesh, std::span<const catalog::Attribute> contract) {
    geometry::requireValidMesh(mesh, "GpuMesh");
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    positions_ = uploadVec3(mesh.positions, catalog::attributeLocation(contract, "a_position"));
    const int normalLocation = catalog::attributeLocation(contract, "a_normal");
    if (!mesh.normals.empty()) {
        normals_ = uploadVec3(mesh.normals, normalLocation);
    } else {
        glDisableVertexAttribArray(static_cast<GLuint>(normalLocation));
        glVertexAttrib3f(static_cast<GLuint>(normalLocation), 0.0f, 0.0f, 1.0f);
    }
    glGenBuffers(1, &indices_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    indexCount_ = mesh.indices.size();
    glBindVertexArray(0);
    gl::throwIfGlError("uploading a mesh");
}

GpuMesh::~GpuMesh() {
    release();
}

GpuMesh::GpuMesh(GpuMesh&& o) noexcept
    : vao_(std::exchange(o.vao_, 0)),
      positions_(std::exchange(o.positions_, 0)),
      normals_(std::exchange(o.normals_, 0)),
      indices_(std::exchange(o.indices_, 0)),
      indexCount_(std::exchange(o.indexCount_, 0)) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& o) noexcept {
    if (this != &o) {
        release();
        vao_ = std::exchange(o.vao_, 0);
        positions_ = std::exchange(o.positions_, 0);
        normals_ = std::exchange(o.normals_, 0);
        indices_ = std::exchange(o.indices_, 0);
        indexCount_ = std::exchange(o.indexCount_, 0);
    }
    return *this;
}

void GpuMesh::release() {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    unsigned buffers[] = {positions_, normals_, indices_};
    for (unsigned b : buffers)
        if (b) glDeleteBuffers(1, &b);
    vao_ = positions_ = normals_ = indices_ = 0;
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace prism::render
