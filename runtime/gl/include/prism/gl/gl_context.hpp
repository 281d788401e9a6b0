// OpenGL 3.3+ core contexts: headless EGL (default), OSMesa, or a GLFW window.
//
// Usage (snippet: examples/snippets/gl_gl_context.cpp):
//
//     #include <iostream>
//
//     #include "prism/gl/gl_context.hpp"
//     auto ctx = prism::gl::createContext();      // EGL, else OSMesa
//     std::cout << ctx->info().renderer << "\n";  // "llvmpipe (LLVM 15.0.6, 256 bits)"
//     try {
//         auto win = prism::gl::createContext(prism::gl::Backend::Glfw, {.width = 800, .height = 600});
//     } catch (const prism::gl::ContextError& e) {  // no display: run under xvfb-run
//         std::cerr << e.what() << "\n";
//     }
//     ctx->makeCurrent();  // before GL calls when several contexts exist; reloads GL if needed
//
// Backends:
//   Egl     EGL on Mesa's surfaceless platform: no display, no window; render into a
//           prism::gl::Framebuffer. Needs libegl1-mesa-dev and libgl1-mesa-dri.
//   OsMesa  Mesa's off-screen library (libosmesa6-dev); has a small default
//           framebuffer (options.width x height) but render into Framebuffers anyway.
//   Glfw    a window (libglfw3-dev). Needs an X display: on a headless machine run
//           the program under `xvfb-run -a ./program`.
//   Vulkan  no GL context at all: the name a program reads from --backend or
//           PRISM_GL_BACKEND to draw through prism::vk instead (prism-render does,
//           docs/vulkan.md); createContext(Vulkan) throws ContextError saying so.
//
// createContext(options) without a backend picks PRISM_GL_BACKEND (egl, osmesa or glfw)
// when that is set, else tries EGL and falls back to OSMesa. Every failure throws
// prism::gl::ContextError saying what is missing and what to install or run.
//
// createContext() makes the new context current and loads the GL functions (glad2);
// GL function pointers are process-wide, so with several contexts call makeCurrent()
// on the one you use next. Contexts are not shared; one thread at a time.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace prism::gl {

enum class Backend { Egl, OsMesa, Glfw, Vulkan };

class ContextError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// "egl", "osmesa", "glfw", "vulkan"
std::string_view backendName(Backend backend);
// Parses "egl" | "osmesa" | "glfw" | "vulkan" (case-insensitive); nullopt for anything else.
std::optional<Backend> parseBackend(std::string_view name);
// The backend named by PRISM_GL_BACKEND; nullopt when unset or empty. Throws
// ContextError when it is set to something that is not a backend name.
std::optional<Backend> backendFromEnvironment();
// Whether this build of Prism includes `backend` as a GL context (it may still fail at run
// time); false for Vulkan, which makes none.
bool isBackendCompiledIn(Backend backend);

struct ContextOptions {
    int majorVersion = 3;  // core profile; at least 3.3 (the loader's API)
    int minorVersion = 3;
    int width = 64;  // GLFW window / OSMesa default framebuffer size
    int height = 64;
    bool debug = false;                 // request a debug context
    std::string windowTitle = "Prism";  // GLFW only
    bool windowVisible = true;          // GLFW only
    bool vsync = true;                  // GLFW only
};

struct ContextInfo {
    Backend backend = Backend::Egl;
    std::string version;   // GL_VERSION
    std::string renderer;  // GL_RENDERER
    std::string vendor;    // GL_VENDOR
    int major = 0, minor = 0;
};

class Context {
  public:
    virtual ~Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    Backend backend() const { return info_.backend; }
    const ContextInfo& info() const { return info_; }

    // Makes this context current on the calling thread and (re)loads GL functions
    // when the previously loaded ones came from another backend.
    virtual void makeCurrent() = 0;
    virtual bool isCurrent() const = 0;

    // Window operations; no-ops (shouldClose() false) for the headless backends.
    virtual void swapBuffers() {}
    virtual void pollEvents() {}
    virtual bool shouldClose() const { return false; }
    virtual void* nativeWindow() const { return nullptr; }  // GLFWwindow* for Glfw
    // Size of the default framebuffer in pixels (0 x 0 for EGL surfaceless).
    virtual int drawableWidth() const = 0;
    virtual int drawableHeight() const = 0;

  protected:
    Context() = default;
    ContextInfo info_;
    friend std::unique_ptr<Context> createContext(Backend, const ContextOptions&);
};

// Creates a context of exactly `backend`, current on this thread with GL loaded.
std::unique_ptr<Context> createContext(Backend backend, const ContextOptions& options = {});
// PRISM_GL_BACKEND if set, else EGL with OSMesa as fallback (see above).
std::unique_ptr<Context> createContext(const ContextOptions& options = {});

}  // namespace prism::gl
