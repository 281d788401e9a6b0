// The usage example of prism/render/offscreen_render.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::render::RenderJob job;
    job.shader = "phong";
    job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
    prism::image::Image8 image = prism::render::renderImage8(cache, job);
    prism::image::ImageF hdr = prism::render::renderImageF(cache, job);  // RGBA32F, for finiteness checks
    // [/snippet]
    return image.width == 512 && prism::image::countNonFinite(hdr) == 0 ? 0 : 1;
}
