// The catalogue view: one mesh drawn live into the window with the catalogue program the
// state picks (prism/render's ProgramCache: a changed axis selects another cached
// program; nothing is rebuilt per frame), lit by the state's lights.
//
//     CatalogueRenderer view(cache, catalog);
//     std::string program = view.draw(state, 0, width, height);  // "phong BLINN=0,FOG=0,..."
#pragma once

#include <optional>
#include <string>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"
#include "viewer_state.hpp"

namespace prism::viewer {

class CatalogueRenderer {
  public:
    CatalogueRenderer(render::ProgramCache& cache, const catalog::Catalog& catalog);
    // The job and full variant the state asks for, at width x height.
    render::RenderJob job(const ViewerState& state, int width, int height) const;
    // Draws into the bound default framebuffer, in the width x height viewport whose left
    // edge is `left`; returns "<shader> <variant>".
    std::string draw(ViewerState& state, int left, int width, int height);
    const render::GpuMesh& mesh() const { return *gpu_; }

  private:
    render::ProgramCache& cache_;
    const catalog::Catalog& catalog_;
    std::optional<render::GpuMesh> gpu_;
};

}  // namespace prism::viewer
