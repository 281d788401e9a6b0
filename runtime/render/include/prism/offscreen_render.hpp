// One image of one mesh with one catalogue shader, rendered off-screen: the building
// block of prism-render, prism-gallery, the golden-image tests and the benchmarks.
//
//     prism::ProgramCache cache(prism::shaders::kCatalog);
//     prism::RenderJob job;
//     job.shader = "phong";
//     job.mesh = prism::meshForShader("phong", prism::namedMesh("torus"));
//     prism::Image8 image = prism::renderImage8(cache, job);
//     prism::ImageF hdr = prism::renderImageF(cache, job);    // RGBA32F, for finiteness checks
//
// The mesh is framed by the default camera (eye at (0, 0.6, 3.2) looking at the origin)
// with the default lights unless the job says otherwise. Needs a current context.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>

#include "prism/camera.hpp"
#include "prism/framebuffer.hpp"
#include "prism/image.hpp"
#include "prism/mesh.hpp"
#include "prism/program_cache.hpp"
#include "prism/scene_lighting.hpp"

namespace prism {

// A key light from the upper right front and a weaker fill light from the left, plus ambient.
Lights defaultLights();
Camera defaultCamera();

struct RenderJob {
    std::string shader = "phong";
    VariantValues variant;
    geometry::Mesh mesh;  // already prepared with meshForShader()
    glm::mat4 world{1.0f};
    Material material;
    Lights lights = defaultLights();
    std::optional<Fog> fog;  // with fog, a shader that has a FOG axis runs its FOG=1 variant
    // The variant is derived from lights and fog (prism/feature_variants.hpp); `variant`
    // fixes other axes (BLINN) or overrides the derived ones.
    Camera camera = defaultCamera();
    int width = 512;
    int height = 512;
    glm::vec4 background{0.05f, 0.06f, 0.08f, 1.0f};
};

Image8 renderImage8(ProgramCache& cache, const RenderJob& job);
ImageF renderImageF(ProgramCache& cache, const RenderJob& job);

// The variant a job runs: derived from its lights and fog (the smallest light loops
// that hold its lights, FOG only with fog), with the job's own values on top.
VariantValues variantForJob(const ProgramCache& cache, const RenderJob& job);

// Draws into whatever framebuffer is bound (viewport already set); for repeated
// frames in benchmarks and the viewer, with the mesh already uploaded.
class GpuMesh;
void drawJob(ProgramCache& cache, const RenderJob& job, const GpuMesh& mesh);

}  // namespace prism
