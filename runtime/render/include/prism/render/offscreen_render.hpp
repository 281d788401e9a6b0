// One image of one mesh with one catalogue shader, rendered off-screen: the building
// block of prism-render, prism-gallery, the golden-image tests and the benchmarks.
//
// Usage (snippet: examples/snippets/render_offscreen_render.cpp):
//
//     #include "prism/render/offscreen_render.hpp"
//     #include "prism/render/shader_meshes.hpp"
//     #include "prism/shaders.hpp"
//     prism::render::ProgramCache cache(prism::shaders::kCatalog);
//     prism::render::RenderJob job;
//     job.shader = "phong";
//     job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
//     prism::image::Image8 image = prism::render::renderImage8(cache, job);
//     prism::image::ImageF hdr = prism::render::renderImageF(cache, job);  // RGBA32F, for finiteness checks
//
// The mesh is framed by the default camera (eye at (0, 0.6, 3.2) looking at the origin)
// with the default lights unless the job says otherwise. Needs a current context.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>

#include "prism/view/camera.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/image/image.hpp"
#include "prism/geometry/mesh.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/view/lighting.hpp"

namespace prism::render {

// A key light from the upper right front and a weaker fill light from the left, plus ambient.
view::Lights defaultLights();
view::Camera defaultCamera();

struct RenderJob {
    std::string shader = "phong";
    VariantValues variant;
    geometry::Mesh mesh;  // already prepared with meshForShader()
    glm::mat4 world{1.0f};
    view::Material material;
    view::Lights lights = defaultLights();
    std::optional<view::Fog> fog;  // with fog, a shader that has a FOG axis runs its FOG=1 variant
    // The variant is derived from lights and fog (prism/render/feature_variants.hpp); `variant`
    // fixes other axes (BLINN) or overrides the derived ones.
    view::Camera camera = defaultCamera();
    int width = 512;
    int height = 512;
    glm::vec4 background{0.05f, 0.06f, 0.08f, 1.0f};
};

image::Image8 renderImage8(ProgramCache& cache, const RenderJob& job);
image::ImageF renderImageF(ProgramCache& cache, const RenderJob& job);

// The variant a job runs: derived from its lights and fog (the smallest light loops
// that hold its lights, FOG only with fog), with the job's own values on top.
VariantValues variantForJob(const ProgramCache& cache, const RenderJob& job);

// Draws into whatever framebuffer is bound (viewport already set); for repeated
// frames in benchmarks and the viewer, with the mesh already uploaded.
class GpuMesh;
void drawJob(ProgramCache& cache, const RenderJob& job, const GpuMesh& mesh);

}  // namespace prism::render
