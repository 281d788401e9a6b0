// The GLFW backend: a window with a GL core context, for interactive programs.
// GLFW 3.3 on Linux needs an X display; headless machines run under xvfb-run.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <mutex>
#include <string>

#include "context_backends.hpp"
#include "gl_loader.hpp"

namespace prism::gl::detail {
namespace {

std::mutex gGlfwMutex;
int gGlfwUsers = 0;
std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "?");
}

GlProc glfwLoader(const char* name) {
    return reinterpret_cast<GlProc>(glfwGetProcAddress(name));
}

void acquireGlfw() {
    std::lock_guard lock(gGlfwMutex);
    if (gGlfwUsers++ > 0) return;
    glfwSetErrorCallback(&onGlfwError);
    gLastGlfwError.clear();
    if (!glfwInit()) {
        gGlfwUsers = 0;
        throw ContextError("prism: GLFW backend: glfwInit failed (" + gLastGlfwError +
                           "). GLFW needs an X display: on a headless machine run the program under "
                           "`xvfb-run -a <program>`, or use PRISM_GL_BACKEND=egl for off-screen rendering");
    }
}

void releaseGlfw() {
    std::lock_guard lock(gGlfwMutex);
    if (--gGlfwUsers > 0) return;
    glfwTerminate();
    forgetGlFunctions(&glfwLoader);
}

class GlfwContext final : public Context {
  public:
    explicit GlfwContext(const ContextOptions& options) {
        acquireGlfw();
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, options.majorVersion);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, options.minorVersion);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_VISIBLE, options.windowVisible ? GLFW_TRUE : GLFW_FALSE);
        gLastGlfwError.clear();
        window_ = glfwCreateWindow(options.width, options.height, options.windowTitle.c_str(), nullptr, nullptr);
        if (!window_) {
            releaseGlfw();
            throw ContextError("prism: GLFW backend: glfwCreateWindow with a GL " +
                               std::to_string(options.majorVersion) + "." + std::to_string(options.minorVersion) +
                               " core context failed (" + gLastGlfwError + ")");
        }
        try {
            makeCurrent();
        } catch (...) {
            glfwDestroyWindow(window_);
            releaseGlfw();
            throw;
        }
        glfwSwapInterval(options.vsync ? 1 : 0);
    }

    ~GlfwContext() override {
        if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
        glfwDestroyWindow(window_);
        releaseGlfw();
    }

    void makeCurrent() override {
        glfwMakeContextCurrent(window_);
        if (glfwGetCurrentContext() != window_)
            throw ContextError("prism: GLFW backend: glfwMakeContextCurrent failed (" + gLastGlfwError + ")");
        loadGlFunctions(&glfwLoader, "glfw");
    }

    bool isCurrent() const override { return glfwGetCurrentContext() == window_; }
    void swapBuffers() override { glfwSwapBuffers(window_); }
    void pollEvents() override { glfwPollEvents(); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_) != 0; }
    void* nativeWindow() const override { return window_; }

    int drawableWidth() const override {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        return w;
    }
    int drawableHeight() const override {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        return h;
    }

  private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createGlfwContext(const ContextOptions& options) {
    return std::make_unique<GlfwContext>(options);
}

}  // namespace prism::gl::detail
