// GL 4.3 compute entry points through the current backend's get-proc-address
// (see prism/rain/compute.hpp).
#include "prism/rain/compute.hpp"

#include <dlfcn.h>

#include <string>

#include "prism/gl.hpp"
#include "prism/rain/gl_resources.hpp"

namespace prism::rain {
namespace {

using CurrentContextFn = void* (*)();
using GetProcFn = void* (*)(const char*);

template <class F>
F symbol(const char* name) {
    return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

// The lookup of whichever backend has a current context; prism_gl links the backends
// into the program, so their functions are in the global symbol scope.
void* lookup(const char* name) {
    struct Backend {
        const char* current;
        const char* getProc;
    };
    constexpr Backend kBackends[] = {
        {"eglGetCurrentContext", "eglGetProcAddress"},
        {"OSMesaGetCurrentContext", "OSMesaGetProcAddress"},
        {"glfwGetCurrentContext", "glfwGetProcAddress"},
    };
    for (const auto& b : kBackends) {
        auto current = symbol<CurrentContextFn>(b.current);
        if (!current || !current()) continue;
        auto getProc = symbol<GetProcFn>(b.getProc);
        if (!getProc) continue;
        if (void* f = getProc(name)) return f;
    }
    return nullptr;
}

int contextVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

}  // namespace

std::array<std::uint32_t, 2> computeGroups(std::uint32_t count, std::uint32_t groupSize) {
    const std::uint32_t groups = count / groupSize + (count % groupSize ? 1u : 0u);
    if (groups <= 65535u) return {groups, groups ? 1u : 0u};
    const std::uint32_t x = 65535u;
    return {x, groups / x + (groups % x ? 1u : 0u)};
}

void ComputeFunctions::dispatch(std::uint32_t count) const {
    const auto g = computeGroups(count);
    if (g[0] == 0) return;
    dispatchCompute(g[0], g[1], 1);
    detail::countDispatch();
}

bool computeAvailable() {
    if (contextVersion() < 43) return false;
    return lookup("glDispatchCompute") && lookup("glMemoryBarrier");
}

ComputeFunctions loadComputeFunctions() {
    const int version = contextVersion();
    if (version < 43)
        throw ComputeUnavailableError(
            "rain: the GPU particle update needs compute shaders (GL 4.3), but the current context is GL " +
            std::to_string(version / 10) + "." + std::to_string(version % 10) +
            "; create it with ContextOptions{.majorVersion = 4, .minorVersion = 3} (Mesa llvmpipe gives 4.5)");
    ComputeFunctions f;
    f.dispatchCompute = reinterpret_cast<void (*)(unsigned, unsigned, unsigned)>(lookup("glDispatchCompute"));
    f.memoryBarrier = reinterpret_cast<void (*)(unsigned)>(lookup("glMemoryBarrier"));
    if (!f.dispatchCompute || !f.memoryBarrier)
        throw ComputeUnavailableError(
            "rain: glDispatchCompute/glMemoryBarrier not found through the current context's get-proc-address "
            "(EGL, OSMesa or GLFW)");
    return f;
}

}  // namespace prism::rain
