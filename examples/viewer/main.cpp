// viewer: an interactive GLFW window over the catalogue. Needs an X display; on a
// headless machine run it under `xvfb-run -a`.
//   Left/Right, Up/Down  rotate the mesh        S  next shader (and variant)
//   M                    next mesh              +/-  subdivision level
//   Esc                  quit                   the title shows the frame time
//   viewer [--frames N]  (N > 0: quit after N frames; used by the smoke test)
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cstring>
#include <iostream>
#include <string>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include "prism/gl/gl_context.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"

namespace {

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
    long maxFrames = 0;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--frames") == 0) maxFrames = std::stol(argv[i + 1]);
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
        std::optional<prism::render::GpuMesh> gpu;
        prism::render::RenderJob job;
        double smoothedMs = 0.0;
        for (long frame = 0; !context->shouldClose() && (maxFrames == 0 || frame < maxFrames); ++frame) {
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
            glFinish();
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            smoothedMs = frame == 0 ? ms : 0.9 * smoothedMs + 0.1 * ms;
            const std::string title = "Prism viewer - " + job.shader + " " + std::string(variant.name) + " / " +
                                      kMeshes[state.meshIndex] + " subdiv " + std::to_string(state.subdivision) +
                                      " / " + std::to_string(smoothedMs).substr(0, 5) + " ms";
            glfwSetWindowTitle(window, title.c_str());
            context->swapBuffers();
            context->pollEvents();
        }
        std::cout << "viewer: last frame " << smoothedMs << " ms (smoothed)\n";
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
