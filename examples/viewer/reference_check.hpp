// The live accuracy readout of the catalogue view: the exact sphere (the double-precision
// CPU reference of prism/reference/sphere_reference.hpp, as in docs/tradeoffs.md) rendered
// ONCE per camera, lights and material, and the view's current shader, variant and mesh
// rendered off-screen at the same size and compared with it
// (prism/reference/image_metrics.hpp): mean and max channel error in 8-bit units over the
// pixels either covers. Only for the classic shaders (flat, smooth, gouraud, phong without
// BLINN) on the sphere and icosphere meshes, which the reference models.
//
//     ReferenceCheck check;
//     std::string text = check.measure(cache, job, gpuMesh);  // "... mean 0.07 max 161 in 8-bit units; ..."
#pragma once

#include <memory>
#include <string>

#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"

namespace prism::viewer {

inline constexpr int kReferenceSize = 320;  // pixels, square

// Why the reference does not apply to `job` on `mesh` (empty when it does).
std::string referenceUnavailable(const render::RenderJob& job, const std::string& mesh,
                                 const render::VariantValues& variant);

class ReferenceCheck {
  public:
    ReferenceCheck();
    ~ReferenceCheck();
    // Renders `job` (size replaced by kReferenceSize) and compares it with the exact
    // sphere; the reference is rebuilt only when camera, lights, material or model change.
    std::string measure(render::ProgramCache& cache, const render::RenderJob& job, const render::GpuMesh& mesh);
    int referencesRendered() const { return referencesRendered_; }

  private:
    struct Cache;
    std::unique_ptr<Cache> cache_;
    int referencesRendered_ = 0;
};

}  // namespace prism::viewer
