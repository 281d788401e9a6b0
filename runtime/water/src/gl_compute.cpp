// Loading glDispatchCompute and glMemoryBarrier (see gl_compute.hpp). The project's
// loader (glad, GL 3.3 core) lacks them; the backends' get-proc-address functions are
// looked up with dlsym so the water library needs no backend headers or link flags.
#include "gl_compute.hpp"

#include <dlfcn.h>

#include <string>

#include "prism/gl_context.hpp"

namespace prism::water::detail {
namespace {

using GetProc = void* (*)(const char*);
using GetCurrent = void* (*)();

template <class F>
F symbol(const char* name) {
    return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

// The get-proc-address function of the backend whose context is current.
GetProc currentGetProc() {
    if (auto current = symbol<GetCurrent>("OSMesaGetCurrentContext"); current && current())
        return symbol<GetProc>("OSMesaGetProcAddress");
    if (auto current = symbol<GetCurrent>("eglGetCurrentContext"); current && current())
        return symbol<GetProc>("eglGetProcAddress");
    if (auto current = symbol<GetCurrent>("glfwGetCurrentContext"); current && current())
        return symbol<GetProc>("glfwGetProcAddress");
    return nullptr;
}

}  // namespace

int currentGlVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

ComputeFunctions loadComputeFunctions() {
    const int version = currentGlVersion();
    if (version < 43)
        throw gl::ContextError(
            "prism water: the GPU simulation needs GL 4.3 compute shaders, but the current context is GL " +
            std::to_string(version / 10) + "." + std::to_string(version % 10) +
            "; create it with {.majorVersion = 4, .minorVersion = 3} or use the CPU simulation");
    const GetProc getProc = currentGetProc();
    if (!getProc)
        throw gl::ContextError("prism water: no current OSMesa, EGL or GLFW context to load glDispatchCompute from");
    ComputeFunctions f;
    f.dispatchCompute = reinterpret_cast<void (*)(GLuint, GLuint, GLuint)>(getProc("glDispatchCompute"));
    f.memoryBarrier = reinterpret_cast<void (*)(GLbitfield)>(getProc("glMemoryBarrier"));
    if (!f.dispatchCompute || !f.memoryBarrier)
        throw gl::ContextError("prism water: the driver does not provide glDispatchCompute/glMemoryBarrier");
    return f;
}

}  // namespace prism::water::detail
