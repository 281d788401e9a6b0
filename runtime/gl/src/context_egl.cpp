// The EGL backend: a GL core context with no display, no window and no surface, on
// Mesa's surfaceless platform (llvmpipe, the default) or, where that platform is
// missing (NVIDIA's EGL) or PRISM_EGL_PLATFORM=device asks for it, on the first EGL
// device that initialises (EGL_EXT_platform_device); rendering goes into framebuffer
// objects.
#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include "context_backends.hpp"
#include "gl_loader.hpp"

namespace prism::gl::detail {
namespace {

std::string eglErrorName(EGLint e) {
    switch (e) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
        case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
        case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
        default: {
            char hex[32];
            std::snprintf(hex, sizeof hex, "EGL error 0x%x", static_cast<unsigned>(e));
            return hex;
        }
    }
}

[[noreturn]] void fail(const std::string& step, const std::string& hint) {
    throw ContextError("prism: EGL backend: " + step + " failed (" + eglErrorName(eglGetError()) + "); " + hint);
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

GlProc eglLoader(const char* name) {
    return reinterpret_cast<GlProc>(eglGetProcAddress(name));
}

// The surfaceless display is one per process; it is initialised by the first
// context and terminated when the last one goes.
std::mutex gDisplayMutex;
EGLDisplay gDisplay = EGL_NO_DISPLAY;
int gDisplayUsers = 0;

// The first device of EGL_EXT_platform_device that initialises, or EGL_NO_DISPLAY.
EGLDisplay initialiseFirstDevice(const char* clientExtensions, PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!queryDevices) return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices(16, devices, &count)) return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major = 0, minor = 0;
        if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
    }
    return EGL_NO_DISPLAY;
}

EGLDisplay acquireDisplay() {
    std::lock_guard lock(gDisplayMutex);
    if (gDisplayUsers > 0) {
        ++gDisplayUsers;
        return gDisplay;
    }
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay)
        throw ContextError("prism: EGL backend: eglGetPlatformDisplayEXT is missing; install libegl1-mesa-dev");
    const char* platformChoice = std::getenv("PRISM_EGL_PLATFORM");
    const std::string platform = platformChoice ? platformChoice : "";
    if (!platform.empty() && platform != "surfaceless" && platform != "device")
        throw ContextError("prism: EGL backend: PRISM_EGL_PLATFORM='" + platform +
                           "' is not a platform; use 'surfaceless' (Mesa) or 'device' (EGL_EXT_platform_device)");
    const bool haveSurfaceless = hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless");
    if (platform == "device" || (platform.empty() && !haveSurfaceless)) {
        EGLDisplay display = initialiseFirstDevice(clientExtensions, getPlatformDisplay);
        if (display == EGL_NO_DISPLAY)
            throw ContextError("prism: EGL backend: no EGL device initialised and Mesa's surfaceless platform is " +
                               std::string(haveSurfaceless ? "not chosen" : "missing") +
                               " (client extensions: " + std::string(clientExtensions ? clientExtensions : "none") +
                               "); install Mesa's EGL (libegl1-mesa-dev, libegl-mesa0) or use PRISM_GL_BACKEND=osmesa");
        gDisplay = display;
        gDisplayUsers = 1;
        return display;
    }
    if (!haveSurfaceless)
        throw ContextError(
            "prism: EGL backend: the EGL library lacks EGL_MESA_platform_surfaceless (client "
            "extensions: " +
            std::string(clientExtensions ? clientExtensions : "none") +
            "); install Mesa's EGL (libegl1-mesa-dev, libegl-mesa0) or use PRISM_GL_BACKEND=osmesa");
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY)
        fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)", "install libgl1-mesa-dri");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        fail("eglInitialize on the surfaceless platform",
             "Mesa's software rasteriser is needed: install libgl1-mesa-dri, or use PRISM_GL_BACKEND=osmesa");
    gDisplay = display;
    gDisplayUsers = 1;
    return display;
}

void releaseDisplay() {
    std::lock_guard lock(gDisplayMutex);
    if (--gDisplayUsers > 0) return;
    eglTerminate(gDisplay);
    gDisplay = EGL_NO_DISPLAY;
    forgetGlFunctions(&eglLoader);
}

class EglContext final : public Context {
  public:
    explicit EglContext(const ContextOptions& options) : display_(acquireDisplay()) {
        try {
            create(options);
        } catch (...) {
            releaseDisplay();
            throw;
        }
    }

    ~EglContext() override {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        releaseDisplay();
    }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail("eglMakeCurrent", "the context may be current on another thread");
        loadGlFunctions(&eglLoader, "egl");
    }

    bool isCurrent() const override { return eglGetCurrentContext() == context_; }
    int drawableWidth() const override { return 0; }
    int drawableHeight() const override { return 0; }

  private:
    void create(const ContextOptions& options) {
        const char* displayExtensions = eglQueryString(display_, EGL_EXTENSIONS);
        if (!hasExtension(displayExtensions, "EGL_KHR_surfaceless_context"))
            throw ContextError(
                "prism: EGL backend: the display lacks EGL_KHR_surfaceless_context; use "
                "PRISM_GL_BACKEND=osmesa");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)", "this EGL has no desktop GL; use osmesa");

        EGLConfig config = EGL_NO_CONFIG_KHR;
        if (!hasExtension(displayExtensions, "EGL_KHR_no_config_context")) {
            const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            EGLint count = 0;
            if (!eglChooseConfig(display_, wanted, &config, 1, &count) || count < 1)
                fail("eglChooseConfig(EGL_OPENGL_BIT)", "no desktop-GL config; use PRISM_GL_BACKEND=osmesa");
        }

        EGLint attribs[16];
        int n = 0;
        attribs[n++] = EGL_CONTEXT_MAJOR_VERSION;
        attribs[n++] = options.majorVersion;
        attribs[n++] = EGL_CONTEXT_MINOR_VERSION;
        attribs[n++] = options.minorVersion;
        attribs[n++] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
        attribs[n++] = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
        if (options.debug) {
            attribs[n++] = EGL_CONTEXT_OPENGL_DEBUG;
            attribs[n++] = EGL_TRUE;
        }
        attribs[n++] = EGL_NONE;
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attribs);
        if (context_ == EGL_NO_CONTEXT)
            fail("eglCreateContext(GL " + std::to_string(options.majorVersion) + "." +
                     std::to_string(options.minorVersion) + " core)",
                 "the driver may not support this version; llvmpipe offers up to 4.5");
        try {
            makeCurrent();
        } catch (...) {
            eglDestroyContext(display_, context_);
            throw;
        }
    }

    EGLDisplay display_;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createEglContext(const ContextOptions& options) {
    return std::make_unique<EglContext>(options);
}

}  // namespace prism::gl::detail
