// Backend names, the PRISM_GL_BACKEND override and the context factory.
#include <cctype>
#include <cstdlib>

#include "context_backends.hpp"
#include "gl_loader.hpp"
#include "prism/gl/gl_context.hpp"

namespace prism::gl {
namespace {

[[noreturn, maybe_unused]] void throwNotCompiledIn(Backend backend, std::string_view package) {
    throw ContextError("prism: this build has no " + std::string(backendName(backend)) + " backend; install " +
                       std::string(package) +
                       " (scripts/setup.sh) and reconfigure CMake, or pick another backend "
                       "(PRISM_GL_BACKEND=egl|osmesa|glfw)");
}

void checkOptions(const ContextOptions& o) {
    if (o.majorVersion < 3 || (o.majorVersion == 3 && o.minorVersion < 3))
        throw ContextError("prism: GL " + std::to_string(o.majorVersion) + "." + std::to_string(o.minorVersion) +
                           " requested, but Prism needs a 3.3+ core context");
    if (o.width < 1 || o.height < 1)
        throw ContextError("prism: context size must be at least 1x1, got " + std::to_string(o.width) + "x" +
                           std::to_string(o.height));
}

}  // namespace

std::string_view backendName(Backend backend) {
    switch (backend) {
        case Backend::Egl: return "egl";
        case Backend::OsMesa: return "osmesa";
        case Backend::Glfw: return "glfw";
        case Backend::Vulkan: return "vulkan";
    }
    return "?";
}

std::optional<Backend> parseBackend(std::string_view name) {
    std::string lower;
    for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (Backend b : {Backend::Egl, Backend::OsMesa, Backend::Glfw, Backend::Vulkan})
        if (lower == backendName(b)) return b;
    return std::nullopt;
}

std::optional<Backend> backendFromEnvironment() {
    const char* value = std::getenv("PRISM_GL_BACKEND");
    if (!value || !*value) return std::nullopt;
    if (auto b = parseBackend(value)) return b;
    throw ContextError("prism: PRISM_GL_BACKEND='" + std::string(value) +
                       "' is not a backend; use egl, osmesa, glfw or vulkan (or unset it)");
}

bool isBackendCompiledIn(Backend backend) {
    switch (backend) {
#ifdef PRISM_GL_HAVE_EGL
        case Backend::Egl: return true;
#endif
#ifdef PRISM_GL_HAVE_OSMESA
        case Backend::OsMesa: return true;
#endif
#ifdef PRISM_GL_HAVE_GLFW
        case Backend::Glfw: return true;
#endif
        default: return false;
    }
}

std::unique_ptr<Context> createContext(Backend backend, const ContextOptions& options) {
    checkOptions(options);
    std::unique_ptr<Context> ctx;
    switch (backend) {
        case Backend::Egl:
#ifdef PRISM_GL_HAVE_EGL
            ctx = detail::createEglContext(options);
#else
            throwNotCompiledIn(backend, "libegl1-mesa-dev");
#endif
            break;
        case Backend::OsMesa:
#ifdef PRISM_GL_HAVE_OSMESA
            ctx = detail::createOsMesaContext(options);
#else
            throwNotCompiledIn(backend, "libosmesa6-dev");
#endif
            break;
        case Backend::Glfw:
#ifdef PRISM_GL_HAVE_GLFW
            ctx = detail::createGlfwContext(options);
#else
            throwNotCompiledIn(backend, "libglfw3-dev");
#endif
            break;
        case Backend::Vulkan:
            throw ContextError(
                "prism: the vulkan backend draws through Vulkan and makes no GL context (prism-render "
                "--backend vulkan, prism::render::VulkanRenderer; docs/vulkan.md); this program needs GL: use egl "
                "or osmesa");
    }
    const detail::CurrentGlInfo gl = detail::queryCurrentGlInfo();
    ctx->info_.backend = backend;
    ctx->info_.version = gl.version;
    ctx->info_.renderer = gl.renderer;
    ctx->info_.vendor = gl.vendor;
    ctx->info_.major = gl.major;
    ctx->info_.minor = gl.minor;
    if (gl.major * 10 + gl.minor < options.majorVersion * 10 + options.minorVersion)
        throw ContextError("prism: the " + std::string(backendName(backend)) + " backend gave GL " + gl.version +
                           ", older than the requested " + std::to_string(options.majorVersion) + "." +
                           std::to_string(options.minorVersion));
    return ctx;
}

std::unique_ptr<Context> createContext(const ContextOptions& options) {
    if (auto chosen = backendFromEnvironment()) return createContext(*chosen, options);
    try {
        return createContext(Backend::Egl, options);
    } catch (const ContextError& eglError) {
        try {
            return createContext(Backend::OsMesa, options);
        } catch (const ContextError& osmesaError) {
            throw ContextError(std::string("prism: no headless GL context could be created.\n  egl: ") +
                               eglError.what() + "\n  osmesa: " + osmesaError.what());
        }
    }
}

}  // namespace prism::gl
