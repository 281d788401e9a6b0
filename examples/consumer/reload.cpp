// Example consumer of hot reload against an installed Prism: watches what the lit_shaders
// catalogue was built from (the consumer's stage files and tint.glsl, and the installed
// prefix's modules, from lit_shaders_sources.hpp), edits the module named on the command
// line (tests/integration/installed_runtime.sh names the prefix's material.glsl), and
// checks that the next frame draws with the rebuilt program: unicolor red turns blue.
//
//     prism_consumer_reload MATERIAL_GLSL_TO_EDIT
#include <glm/mat4x4.hpp>

#include <chrono>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

// [snippet]
#include "consumer/lit_shaders.hpp"          // the catalogue prism_add_shaders(lit_shaders ...) generated
#include "consumer/lit_shaders_sources.hpp"  // beside it: where its sources lie (kSourceTree)
#include "prism/render/shader_watcher.hpp"
// [/snippet]
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/render/gpu_mesh.hpp"

namespace {

// The centre pixel of a sphere drawn with `program` in plain red, untinted.
prism::image::Rgba8 centre(prism::gl::Program& program) {
    static const prism::geometry::Mesh sphere = prism::geometry::makeIcosphere(1.0f, 2);
    prism::render::GpuMesh mesh(sphere, consumer::lit::kCatalog.contractAttributes);
    prism::gl::Framebuffer target(16, 16);
    target.clear({0.0f, 0.0f, 0.0f, 1.0f});
    prism::view::Camera camera;
    camera.eye = {0.0f, 0.0f, 3.0f};
    program.use();
    prism::render::setFrameUniforms(program, camera, 1.0f, {}, glm::mat4(1.0f), {.color = {1.0f, 0.0f, 0.0f, 1.0f}});
    program.set("u_tint", glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    mesh.draw(program);
    const auto image = target.readImage8();
    return image.at(8, 8);
}

std::string rgb(const prism::image::Rgba8& c) {
    return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: prism_consumer_reload MATERIAL_GLSL_TO_EDIT\n";
        return 2;
    }
    try {
        auto context = prism::gl::createContext();
        // [snippet]
        prism::render::ProgramCache cache(consumer::lit::kCatalog);
        prism::render::ShaderWatcher watcher(cache,
                                             prism::render::ShaderWatchOptions::from(consumer::lit::kSourceTree));
        // In the render loop, on the GL thread: edits are rebuilt and swapped in.
        for (const auto& d : watcher.poll().diagnostics) std::cerr << d;  // path:line:col: error: ...
        prism::gl::Program& program = cache.get("tinted_unicolor");       // the newest good program
        // [/snippet]
        const auto before = centre(program);
        std::ofstream(argv[1], std::ios::app) << "#define u_color u_color.bgra\n";  // red becomes blue
        const auto start = std::chrono::steady_clock::now();
        std::size_t reloaded = 0;
        while (reloaded == 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(5)) {
            const auto result = watcher.poll();
            for (const auto& d : result.diagnostics) std::cerr << d;
            reloaded += result.reloaded.size();
        }
        const auto after = centre(program);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::cout << "prism_consumer_reload: watching " << watcher.watchedFiles().size() << " files with "
                  << (watcher.mechanism() == prism::render::WatchMechanism::Inotify ? "inotify" : "polling")
                  << "; before " << rgb(before) << ", after " << rgb(after) << ", " << ms << " ms after the edit\n";
        const bool ok = before == prism::image::Rgba8{255, 0, 0, 255} && after == prism::image::Rgba8{0, 0, 255, 255};
        std::cout << "reload of an installed module: " << (ok ? "OK" : "FAILED") << "\n";
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "prism_consumer_reload: error: " << e.what() << "\n";
        return 1;
    }
}
