// A geometry::Mesh uploaded to GL: one vertex array with positions and normals bound
// to the locations the binding contract gives `a_position` and `a_normal`. draw(program)
// first checks that the mesh feeds every attribute the program reads: one it does not
// (a misspelled `a_positon` would otherwise read zeros and draw nothing) throws
// MeshAttributeError naming it, with "did you mean".
//
// Usage (snippet: examples/snippets/render_gpu_mesh.cpp):
//
//     #include "prism/render/gpu_mesh.hpp"
//     #include "prism/shaders.hpp"
//     prism::render::GpuMesh gpu(mesh, prism::shaders::kCatalog.contractAttributes);
//     program.use();
//     gpu.draw(program);  // checks the program's attributes, then glDrawElements of every triangle
//
// Needs a current context for its whole life; move-only.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

#include "prism/geometry/mesh.hpp"
#include "prism/gl/handles.hpp"
#include "prism/gl/program.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::render {

// A program reads a vertex attribute that the mesh does not feed (or feeds elsewhere).
class MeshAttributeError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class GpuMesh {
  public:
    GpuMesh(const geometry::Mesh& mesh, std::span<const catalog::Attribute> contract);

    // Throws MeshAttributeError unless this mesh feeds every attribute `program` reads, at
    // the location the program reads it from.
    void requireAttributesOf(const gl::Program& program) const;
    // requireAttributesOf(program), then draw(); `program` must be in use.
    void draw(const gl::Program& program) const;
    // Draws with whatever program is in use, unchecked.
    void draw() const;
    // What the vertex array feeds: a_position, a_normal (a constant (0, 0, 1) without normals).
    const std::vector<gl::AttributeBinding>& attributes() const { return attributes_; }
    std::size_t triangleCount() const { return indexCount_ / 3; }

  private:
    // Declared so that the vertex array is deleted first (members go in reverse order).
    gl::Buffer positions_, normals_, indices_;
    gl::VertexArray vao_;
    std::size_t indexCount_ = 0;
    std::vector<gl::AttributeBinding> attributes_;
};

}  // namespace prism::render
