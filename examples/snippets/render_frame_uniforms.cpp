// The usage example of prism/render/frame_uniforms.hpp, compiled and run by tests/snippets.
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/shaders.hpp"
// [snippet]
#include "prism/render/frame_uniforms.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    prism::gl::Framebuffer target(32, 32);
    target.bind();
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    const prism::view::Lights lights = prism::render::defaultLights();
    const auto& phong = *prism::catalog::findShader(prism::shaders::kCatalog, "phong");
    prism::gl::Program& program =
        cache.get("phong", prism::render::variantFor(phong, prism::render::featuresOf(lights, false)));
    prism::render::GpuMesh gpuMesh(prism::geometry::makeIcosphere(1.0f, 2),
                                   prism::shaders::kCatalog.contractAttributes);
    const prism::view::Camera camera = prism::render::defaultCamera();
    const float aspect = 1.0f;
    const glm::mat4 world(1.0f);
    const prism::view::Material material;
    // [snippet]
    prism::render::setFrameUniforms(program, camera, aspect, lights, world, material);
    gpuMesh.draw();
    // [/snippet]
    return program.unknownUniformReports().empty() && target.readImage8().at(16, 16)[0] > 0 ? 0 : 1;
}
