// docs/runtime.md, "The program cache": programs built on first use and shared, and the
// one-call off-screen render built on it. Compiled and run by tests/snippets
// (snippets.tour_program_cache).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"

int main() {
    auto context = prism::gl::createContext();
    prism::render::ProgramCache cache(prism::shaders::kCatalog);

    prism::gl::Program& blinn = cache.get("phong", {{"BLINN", "1"}});  // built now
    prism::gl::Program& again = cache.get("phong", {{"BLINN", "1"}});  // the same program
    std::cout << cache.size() << " program(s) built\n";                // 1

    // A misspelled shader or variant names what exists instead.
    try {
        cache.get("phongg");
    } catch (const prism::render::UnknownShaderError& e) {
        std::cout << e.what() << "\n";
    }

    // The whole draw in one call: the default camera and lights, the mesh the shader wants
    // (flat needs face normals on vertices split per face, the others vertex normals).
    prism::render::RenderJob job;
    job.shader = "gouraud";
    job.mesh = prism::render::meshForShader("gouraud", prism::render::namedMesh("trefoil"));
    job.width = job.height = 200;
    prism::image::writePng("out/trefoil.png", prism::render::renderImage8(cache, job));
    return &blinn == &again && cache.size() == 2 ? 0 : 1;
}
// [/snippet]
