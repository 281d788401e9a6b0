// A geometry::Mesh uploaded to GL: one vertex array with positions and normals bound
// to the locations the binding contract gives `a_position` and `a_normal`.
//
// Usage (snippet: examples/snippets/render_gpu_mesh.cpp):
//
//     #include "prism/render/gpu_mesh.hpp"
//     #include "prism/shaders.hpp"
//     prism::render::GpuMesh gpu(mesh, prism::shaders::kCatalog.contractAttributes);
//     gpu.draw();   // glDrawElements of every triangle, with the program already in use
//
// Needs a current context for its whole life; move-only.
#pragma once

#include <cstddef>
#include <span>

#include "prism/geometry/mesh.hpp"
#include "prism/gl/handles.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::render {

class GpuMesh {
  public:
    GpuMesh(const geometry::Mesh& mesh, std::span<const catalog::Attribute> contract);

    void draw() const;
    std::size_t triangleCount() const { return indexCount_ / 3; }

  private:
    // Declared so that the vertex array is deleted first (members go in reverse order).
    gl::Buffer positions_, normals_, indices_;
    gl::VertexArray vao_;
    std::size_t indexCount_ = 0;
};

}  // namespace prism::render
