// The live catalogue view (catalogue_view.hpp).
#include "catalogue_view.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <stdexcept>

#include "prism/gl/gl.hpp"
#include "prism/render/shader_meshes.hpp"
#include "variant_choice.hpp"

namespace prism::viewer {

CatalogueRenderer::CatalogueRenderer(render::ProgramCache& cache, const catalog::Catalog& catalog)
    : cache_(cache), catalog_(catalog) {}

render::RenderJob CatalogueRenderer::job(const ViewerState& state, int width, int height) const {
    const auto& c = state.catalogue;
    const catalog::Shader* shader = catalog::findShader(catalog_, c.shader);
    if (!shader) throw std::invalid_argument("unknown shader '" + c.shader + "'");
    render::RenderJob job;
    job.shader = c.shader;
    job.lights = c.lights;
    job.fog = c.fog;
    job.material = c.material;
    job.variant = effectiveVariant(*shader, render::featuresOf(c.lights, c.fog.has_value()), c.picks);
    job.width = std::max(width, 1);
    job.height = std::max(height, 1);
    job.world = glm::rotate(glm::mat4(1.0f), c.pitch, glm::vec3(1, 0, 0)) *
                glm::rotate(glm::mat4(1.0f), c.yaw, glm::vec3(0, 1, 0));
    return job;
}

std::string CatalogueRenderer::draw(ViewerState& state, int left, int width, int height) {
    const render::RenderJob j = job(state, width, height);
    if (state.meshDirty || !gpu_) {
        gpu_.emplace(
            render::meshForShader(j.shader, render::namedMesh(state.catalogue.mesh, state.catalogue.subdivision)),
            catalog_.contractAttributes);
        state.meshDirty = false;
    }
    glViewport(left, 0, j.width, j.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(left, 0, j.width, j.height);
    glClearColor(j.background.r, j.background.g, j.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    render::drawJob(cache_, j, *gpu_);
    return j.shader + " " + variantLabel(j.variant);
}

}  // namespace prism::viewer
