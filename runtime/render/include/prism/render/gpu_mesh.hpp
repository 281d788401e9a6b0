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
#include "prism/catalog/shader_catalog.hpp"

namespace prism::render {

class GpuMesh {
  public:
    GpuMesh(const geometry::Mesh& mesh, std::span<const catalog::Attribute> contract);
    ~GpuMesh();
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    void draw() const;
    std::size_t triangleCount() const { return indexCount_ / 3; }

  private:
    void release();
    unsigned vao_ = 0, positions_ = 0, normals_ = 0, indices_ = 0;
    std::size_t indexCount_ = 0;
};

}  // namespace prism::render
