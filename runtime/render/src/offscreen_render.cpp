// Off-screen rendering of a RenderJob (see prism/render/offscreen_render.hpp).
#include "prism/render/offscreen_render.hpp"

#include <stdexcept>

#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/gl.hpp"
#include "prism/render/gpu_mesh.hpp"

namespace prism::render {

view::Lights defaultLights() {
    view::Lights l;
    l.ambient = glm::vec3(0.12f);
    l.directional.push_back({glm::vec3(-0.5f, -0.6f, -0.65f), glm::vec3(0.85f)});
    l.directional.push_back({glm::vec3(0.7f, 0.2f, -0.4f), glm::vec3(0.2f, 0.22f, 0.3f)});
    return l;
}

view::Camera defaultCamera() {
    view::Camera c;
    c.eye = {0.0f, 0.6f, 3.2f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.fovYDegrees = 45.0f;
    c.nearPlane = 0.1f;
    c.farPlane = 50.0f;
    return c;
}

VariantValues variantForJob(const ProgramCache& cache, const RenderJob& job) {
    const auto* shader = catalog::findShader(cache.catalog(), job.shader);
    if (!shader) return job.variant;  // the cache reports the unknown shader
    return variantFor(*shader, featuresOf(job.lights, job.fog.has_value()), job.variant);
}

void drawJob(ProgramCache& cache, const RenderJob& job, const GpuMesh& mesh) {
    gl::Program& program = cache.get(job.shader, variantForJob(cache, job));
    program.use();
    setFrameUniforms(program, job.camera, static_cast<float>(job.width) / static_cast<float>(job.height), job.lights,
                     job.world, job.material, job.fog ? &*job.fog : nullptr);
    mesh.draw(program);
}

namespace {

void renderInto(gl::Framebuffer& fb, ProgramCache& cache, const RenderJob& job) {
    if (job.width <= 0 || job.height <= 0 || job.width > 16384 || job.height > 16384)
        throw std::invalid_argument("render size must be between 1x1 and 16384x16384");
    GpuMesh mesh(job.mesh, cache.catalog().contractAttributes);
    fb.bind();
    fb.clear({job.background.r, job.background.g, job.background.b, job.background.a});
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    drawJob(cache, job, mesh);
    glFinish();
    gl::throwIfGlError("rendering " + job.shader);
}

}  // namespace

image::Image8 renderImage8(ProgramCache& cache, const RenderJob& job) {
    gl::Framebuffer fb(job.width, job.height, gl::ColorFormat::Rgba8);
    renderInto(fb, cache, job);
    return fb.readImage8();
}

image::ImageF renderImageF(ProgramCache& cache, const RenderJob& job) {
    gl::Framebuffer fb(job.width, job.height, gl::ColorFormat::Rgba32F);
    renderInto(fb, cache, job);
    return fb.readImageF();
}

}  // namespace prism::render
