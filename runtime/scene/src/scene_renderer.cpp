// Scene drawing with minimal, shared programs (see prism/scene_renderer.hpp).
#include "prism/scene_renderer.hpp"

#include "prism/feature_variants.hpp"
#include "prism/frame_uniforms.hpp"
#include "prism/framebuffer.hpp"
#include "prism/gl.hpp"
#include "prism/gpu_mesh.hpp"
#include "prism/shader_meshes.hpp"

namespace prism {

Image8 SceneRenderer::render(const Scene& scene) {
    const FeatureSet features = featuresOf(scene.lights, scene.fog.has_value());
    const float aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
    lastFrame_ = {};

    gl::Framebuffer fb(scene.width, scene.height, gl::ColorFormat::Rgba8);
    fb.bind();
    const glm::vec4 background = scene.fog ? glm::vec4(scene.fog->color, 1.0f) : scene.background;
    fb.clear({background.r, background.g, background.b, background.a});
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);

    for (const auto& object : scene.objects) {
        const auto* shader = catalog::findShader(programs_.catalog(), object.shader);
        if (!shader) programs_.variantOf(object.shader, {});  // throws UnknownShaderError with the list
        const VariantValues variant = variantFor(*shader, features, object.variantOverrides);
        gl::Program& program = programs_.get(object.shader, variant);
        GpuMesh mesh(meshForShader(object.shader, namedMesh(object.mesh, object.subdivision)),
                     programs_.catalog().contractAttributes);
        program.use();
        setFrameUniforms(program, scene.camera, aspect, scene.lights, object.world, object.material,
                         scene.fog ? &*scene.fog : nullptr);
        mesh.draw();
        ++lastFrame_.draws;
        lastFrame_.variants.push_back(object.shader + " " +
                                      std::string(programs_.variantOf(object.shader, variant).name));
    }
    glFinish();
    gl::throwIfGlError("rendering " + scene.file);
    return fb.readImage8();
}

}  // namespace prism
