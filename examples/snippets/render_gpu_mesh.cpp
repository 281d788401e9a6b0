// The usage example of prism/render/gpu_mesh.hpp, compiled and run by tests/snippets.
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/program_cache.hpp"
// [snippet]
#include "prism/render/gpu_mesh.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    prism::gl::Framebuffer target(16, 16);
    target.bind();
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::gl::Program& program = cache.get("unicolor");
    const prism::geometry::Mesh mesh = prism::geometry::makeCube();
    // [snippet]
    prism::render::GpuMesh gpu(mesh, prism::shaders::kCatalog.contractAttributes);
    program.use();
    gpu.draw(program);  // checks the program's attributes, then glDrawElements of every triangle
    // [/snippet]
    return gpu.triangleCount() == 12 ? 0 : 1;
}
