// The usage example of prism/render/shader_watcher.hpp, compiled and run by tests/snippets
// (on Prism's own source tree, which nothing edits while it runs).
#include <iostream>
#include <string>

#include "prism/gl/gl_context.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"

int main() {
    auto context = prism::gl::createContext();
    const std::string sourceTree = PRISM_SOURCE_DIR;
    // [snippet]
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::render::ShaderWatchOptions options;
    options.sourceRoot = sourceTree;  // the tree the catalogue was built from
    prism::render::ShaderWatcher watcher(cache, options);
    prism::render::RenderJob job;
    job.shader = "phong";
    job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
    for (int frame = 0; frame < 3; ++frame) {                                  // the render loop, on the GL thread
        for (const auto& d : watcher.poll().diagnostics) std::cerr << d;       // path:line:col: error: ...
        prism::image::Image8 image = prism::render::renderImage8(cache, job);  // newest good program
    }
    // [/snippet]
    return watcher.poll().diagnostics.empty() && cache.size() == 1 ? 0 : 1;
}
