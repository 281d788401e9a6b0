// The exact-sphere error readout (reference_check.hpp), with the reference renderer and
// metrics of prism_reference that the tradeoff bench uses too.
#include "reference_check.hpp"

#include <array>
#include <cstdio>
#include <optional>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/reference/image_metrics.hpp"
#include "prism/reference/sphere_reference.hpp"

namespace prism::viewer {

namespace {
bool diffuseOnly(const std::string& shader) {
    return shader == "flat" || shader == "smooth";
}

std::string keyOf(const render::RenderJob& job, bool withSpecular) {
    std::string key = withSpecular ? "s" : "d";
    auto add = [&](float v) { key += std::to_string(v) + ","; };
    auto add3 = [&](const glm::vec3& v) { add(v.x), add(v.y), add(v.z); };
    add3(job.camera.eye), add3(job.camera.target), add(job.camera.fovYDegrees);
    add3(job.lights.ambient);
    for (const auto& l : job.lights.directional) add3(l.direction), add3(l.color);
    for (const auto& l : job.lights.points) add3(l.position), add3(l.color);
    add3(glm::vec3(job.material.color)), add(job.material.shininess), add(job.material.specular);
    return key;
}
}  // namespace

std::string referenceUnavailable(const render::RenderJob& job, const std::string& mesh,
                                 const render::VariantValues& variant) {
    if (job.shader != "flat" && job.shader != "smooth" && job.shader != "gouraud" && job.shader != "phong")
        return "no reference for " + job.shader + " (the exact sphere covers flat, smooth, gouraud, phong)";
    if (mesh != "sphere" && mesh != "icosphere") return "no reference for mesh " + mesh + " (sphere, icosphere only)";
    for (const auto& [n, v] : variant)
        if (n == "BLINN" && v == "1") return "no reference for BLINN=1 (the reference models Phong specular)";
    if (job.fog) return "no reference with fog";
    return {};
}

struct ReferenceCheck::Cache {
    std::string key;
    reference::SphereReference reference;
    std::optional<gl::Framebuffer> target;
};

ReferenceCheck::ReferenceCheck() : cache_(std::make_unique<Cache>()) {}
ReferenceCheck::~ReferenceCheck() = default;

std::string ReferenceCheck::measure(render::ProgramCache& cache, const render::RenderJob& viewJob,
                                    const render::GpuMesh& mesh) {
    render::RenderJob job = viewJob;
    job.width = job.height = kReferenceSize;
    job.background.a = 0.0f;  // alpha 0 marks background for the coverage test
    const bool withSpecular = !diffuseOnly(job.shader);
    const std::string key = keyOf(job, withSpecular);
    if (key != cache_->key) {
        reference::SphereScene scene;
        scene.camera = job.camera;
        scene.lights = job.lights;
        scene.material = job.material;
        scene.width = scene.height = kReferenceSize;
        scene.background = glm::dvec3(job.background.r, job.background.g, job.background.b);
        cache_->reference = reference::renderSphereReference(scene, withSpecular);
        cache_->key = key;
        ++referencesRendered_;
    }
    if (!cache_->target) cache_->target.emplace(kReferenceSize, kReferenceSize, gl::ColorFormat::Rgba8);
    const auto& fb = *cache_->target;
    fb.clear({job.background.r, job.background.g, job.background.b, 0.0f});
    glEnable(GL_DEPTH_TEST);
    render::drawJob(cache, job, mesh);
    const image::Image8 frame = fb.readImage8();
    gl::Framebuffer::bindDefault();
    const reference::Metrics m = reference::compareWithReference(frame, cache_->reference.image);
    char text[200];
    std::snprintf(text, sizeof text,
                  "vs exact sphere (%dx%d): mean %.2f max %d in 8-bit units; inside both: max %d; "
                  "silhouette: %zu px differ",
                  kReferenceSize, kReferenceSize, m.union_.mean, m.union_.max, m.interior.max,
                  m.renderOnly + m.referenceOnly);
    return text;
}

}  // namespace prism::viewer
