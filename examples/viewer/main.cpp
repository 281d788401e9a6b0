// viewer: an interactive GLFW window over the catalogue. Needs an X display; on a
// headless machine run it under `xvfb-run -a`.
//   Left/Right, Up/Down  rotate the mesh        S  next shader (and variant)
//   M                    next mesh              +/-  subdivision level
//   Esc                  quit                   the title shows the frame time
//
//   viewer [--frames N] [--watch] [--source-root DIR] [--screenshot PNG]
//     --frames N         quit after N frames (0 = run until closed; the smoke tests use it)
//     --watch            hot reload: watch the stage and module files the catalogue was
//                        built from, rebuild edited shaders in process and swap them in;
//                        an error keeps the last good program and is printed and shown
//                        as a red strip at the top of the window (docs/hot-reload.md)
//     --source-root DIR  the tree to watch (default: the checkout the viewer was built from)
//     --screenshot PNG   write the last frame to PNG on exit
// SIGINT/SIGTERM end the loop cleanly (the screenshot is still written).
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include "error_overlay.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"

namespace {

constexpr const char* kUsage =
    "usage: viewer [--frames N] [--watch] [--source-root DIR] [--screenshot PNG]\n";

struct ViewerArgs {
    long frames = 0;
    bool watch = false;
    std::string sourceRoot = PRISM_SOURCE_DIR;
    std::string screenshot;
};

// nullopt with `exitCode` set: print nothing more and exit (2 = usage error, 0 = --help).
std::optional<ViewerArgs> parseArgs(int argc, char** argv, int& exitCode) {
    ViewerArgs args;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        if (a == "--help" || a == "-h") {
            std::cout << kUsage;
            exitCode = 0;
            return std::nullopt;
        }
        if (a == "--watch") {
            args.watch = true;
            continue;
        }
        if (a == "--frames" || a == "--source-root" || a == "--screenshot") {
            const char* v = value();
            if (!v) {
                std::cerr << "viewer: error: " << a << " needs a value\n" << kUsage;
                exitCode = 2;
                return std::nullopt;
            }
            if (a == "--source-root") {
                args.sourceRoot = v;
            } else if (a == "--screenshot") {
                args.screenshot = v;
            } else {
                char* end = nullptr;
                args.frames = std::strtol(v, &end, 10);
                if (*v == '\0' || *end != '\0' || args.frames < 0) {
                    std::cerr << "viewer: error: --frames wants a count >= 0, got '" << v << "'\n" << kUsage;
                    exitCode = 2;
                    return std::nullopt;
                }
            }
            continue;
        }
        std::cerr << "viewer: error: unknown option '" << a << "'\n" << kUsage;
        exitCode = 2;
        return std::nullopt;
    }
    return args;
}

volatile std::sig_atomic_t gStopRequested = 0;
void onStopSignal(int) {
    gStopRequested = 1;
}

// The overlay shows the first outstanding error, its path relative to the watched tree.
std::string overlayText(const std::vector<std::string>& errors, const std::string& root) {
    if (errors.empty()) return {};
    std::string text = errors.front();
    for (std::size_t at; (at = text.find(root + "/")) != std::string::npos;) text.erase(at, root.size() + 1);
    if (errors.size() > 1) text += "(+" + std::to_string(errors.size() - 1) + " more errors: see the console)";
    return text;
}

prism::image::Image8 readBackBuffer(int width, int height) {
    prism::image::Image8 image(width, height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.data.data());
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y)  // GL's row 0 is the bottom
        std::swap_ranges(image.data.begin() + static_cast<std::ptrdiff_t>(y * row),
                         image.data.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                         image.data.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
    return image;
}

struct ViewerState {
    std::size_t shaderIndex = 0, variantIndex = 0, meshIndex = 0;
    unsigned subdivision = 3;
    float yaw = 0.0f, pitch = 0.3f;
    bool meshDirty = true;
};

const char* const kMeshes[] = {"sphere", "icosphere", "torus", "cube", "trefoil"};

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_RELEASE) return;
    auto& s = *static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
    const auto& shaders = prism::shaders::kCatalog.shaders;
    switch (key) {
        case GLFW_KEY_ESCAPE:
            glfwSetWindowShouldClose(window, GLFW_TRUE);
            break;
        case GLFW_KEY_LEFT:
            s.yaw -= 0.1f;
            break;
        case GLFW_KEY_RIGHT:
            s.yaw += 0.1f;
            break;
        case GLFW_KEY_UP:
            s.pitch -= 0.1f;
            break;
        case GLFW_KEY_DOWN:
            s.pitch += 0.1f;
            break;
        case GLFW_KEY_S:
            if (++s.variantIndex >= shaders[s.shaderIndex].variants.size()) {
                s.variantIndex = 0;
                s.shaderIndex = (s.shaderIndex + 1) % shaders.size();
            }
            s.meshDirty = true;  // flat needs other normals
            break;
        case GLFW_KEY_M:
            s.meshIndex = (s.meshIndex + 1) % std::size(kMeshes);
            s.meshDirty = true;
            break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            if (s.subdivision < 6) ++s.subdivision;
            s.meshDirty = true;
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            if (s.subdivision > 0) --s.subdivision;
            s.meshDirty = true;
            break;
        default:
            break;
    }
}

}  // namespace

int main(int argc, char** argv) {
    int exitCode = 0;
    const auto args = parseArgs(argc, argv, exitCode);
    if (!args) return exitCode;
    const long maxFrames = args->frames;
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    try {
        prism::gl::ContextOptions options;
        options.width = 800;
        options.height = 800;
        options.windowTitle = "Prism viewer";
        options.vsync = maxFrames == 0;
        auto context = prism::gl::createContext(prism::gl::Backend::Glfw, options);
        auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
        ViewerState state;
        glfwSetWindowUserPointer(window, &state);
        glfwSetKeyCallback(window, onKey);

        prism::render::ProgramCache cache(prism::shaders::kCatalog);
        std::unique_ptr<prism::render::ShaderWatcher> watcher;
        prism::viewer::ErrorOverlay overlay;
        if (args->watch) {
            prism::render::ShaderWatchOptions watchOptions;
            watchOptions.sourceRoot = args->sourceRoot;
            watcher = std::make_unique<prism::render::ShaderWatcher>(cache, watchOptions);
            std::cout << "viewer: watching " << watcher->watchedFiles().size() << " files under "
                      << args->sourceRoot << std::endl;
        }
        std::optional<prism::render::GpuMesh> gpu;
        prism::render::RenderJob job;
        double smoothedMs = 0.0;
        bool screenshotWritten = false;
        for (long frame = 0; !context->shouldClose() && !gStopRequested && (maxFrames == 0 || frame < maxFrames);
             ++frame) {
            if (watcher) {
                const auto result = watcher->poll();
                for (const auto& f : result.changedFiles) std::cout << "viewer: changed " << f << "\n";
                for (const auto& r : result.reloaded) std::cout << "viewer: reloaded " << r << "\n";
                for (const auto& d : result.diagnostics) std::cerr << d;
                if (result.checked) {
                    const auto text = overlayText(watcher->errors(), watcher->sourceRoot());
                    if (text != overlay.text())
                        std::cout << "viewer: overlay " << (text.empty() ? "cleared" : "shows: " + text) << std::endl;
                    overlay.setText(text);
                }
                std::cerr.flush();
            }
            const auto start = std::chrono::steady_clock::now();
            const auto& shader = prism::shaders::kCatalog.shaders[state.shaderIndex];
            const auto& variant = shader.variants[state.variantIndex];
            job.shader = std::string(shader.name);
            job.variant.clear();
            for (const auto& d : variant.defines) job.variant.emplace_back(d.name, d.value);
            if (state.meshDirty) {
                gpu.emplace(
                    prism::render::meshForShader(job.shader, prism::render::namedMesh(kMeshes[state.meshIndex], state.subdivision)),
                    prism::shaders::kCatalog.contractAttributes);
                state.meshDirty = false;
            }
            int w = 0, h = 0;
            glfwGetFramebufferSize(window, &w, &h);
            job.width = std::max(w, 1);
            job.height = std::max(h, 1);
            job.world = glm::rotate(glm::mat4(1.0f), state.pitch, glm::vec3(1, 0, 0)) *
                        glm::rotate(glm::mat4(1.0f), state.yaw, glm::vec3(0, 1, 0));
            glViewport(0, 0, job.width, job.height);
            glClearColor(job.background.r, job.background.g, job.background.b, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            prism::render::drawJob(cache, job, *gpu);
            overlay.draw(job.width, job.height);
            glFinish();
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            smoothedMs = frame == 0 ? ms : 0.9 * smoothedMs + 0.1 * ms;
            const std::string title = "Prism viewer - " + job.shader + " " + std::string(variant.name) + " / " +
                                      kMeshes[state.meshIndex] + " subdiv " + std::to_string(state.subdivision) +
                                      " / " + std::to_string(smoothedMs).substr(0, 5) + " ms";
            glfwSetWindowTitle(window, title.c_str());
            const bool lastFrame = gStopRequested || (maxFrames > 0 && frame + 1 == maxFrames);
            if (!args->screenshot.empty() && lastFrame && !screenshotWritten) {
                prism::image::writePng(args->screenshot, readBackBuffer(job.width, job.height));
                std::cout << "viewer: wrote " << args->screenshot << std::endl;
                screenshotWritten = true;
            }
            context->swapBuffers();
            context->pollEvents();
        }
        if (!args->screenshot.empty() && !screenshotWritten) {  // stopped between two frames
            prism::image::writePng(args->screenshot, readBackBuffer(job.width, job.height));
            std::cout << "viewer: wrote " << args->screenshot << std::endl;
        }
        std::cout << "viewer: last frame " << smoothedMs << " ms (smoothed)\n";
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
