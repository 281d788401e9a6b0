// Loads the glad2 function pointers through the current backend's get-proc-address
// function, reloading only when the backend changes.
#include "gl_loader.hpp"

#include <mutex>

#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"

namespace prism::gl::detail {
namespace {

std::mutex gLoaderMutex;
GlProcLoader gLoadedWith = nullptr;

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

void loadGlFunctions(GlProcLoader loader, std::string_view backendName) {
    std::lock_guard lock(gLoaderMutex);
    if (loader == gLoadedWith) return;
    const int version = gladLoadGL(loader);
    if (version == 0) {
        gLoadedWith = nullptr;
        throw ContextError("prism: could not load the GL 3.3 core functions through the " + std::string(backendName) +
                           " backend (the context is current but glGetString/GL entry points are missing); "
                           "check that Mesa's libgl1-mesa-dri is installed");
    }
    gLoadedWith = loader;
}

void forgetGlFunctions(GlProcLoader loader) {
    std::lock_guard lock(gLoaderMutex);
    if (gLoadedWith == loader) gLoadedWith = nullptr;
}

CurrentGlInfo queryCurrentGlInfo() {
    CurrentGlInfo info;
    info.version = glString(GL_VERSION);
    info.renderer = glString(GL_RENDERER);
    info.vendor = glString(GL_VENDOR);
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    info.major = major;
    info.minor = minor;
    return info;
}

}  // namespace prism::gl::detail
