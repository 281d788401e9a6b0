// The OSMesa backend: Mesa's off-screen GL in a core 3.3+ context, made current on a
// small client-memory buffer. This file must not include the glad loader header
// (GL/osmesa.h pulls in GL/gl.h, which clashes with it).
#include <GL/osmesa.h>

#include <string>
#include <vector>

#include "context_backends.hpp"
#include "gl_loader.hpp"

namespace prism::gl::detail {
namespace {

GlProc osmesaLoader(const char* name) {
    return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name));
}

class OsMesaContext final : public Context {
  public:
    explicit OsMesaContext(const ContextOptions& options)
        : width_(options.width),
          height_(options.height),
          buffer_(static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height) * 4) {
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               24,
                               OSMESA_STENCIL_BITS,
                               8,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               options.majorVersion,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               options.minorVersion,
                               0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_)
            throw ContextError("prism: OSMesa backend: OSMesaCreateContextAttribs(GL " +
                               std::to_string(options.majorVersion) + "." + std::to_string(options.minorVersion) +
                               " core) failed; Mesa's OSMesa (libosmesa6) offers core contexts up to 4.5 with "
                               "llvmpipe - check the version, or use PRISM_GL_BACKEND=egl");
        try {
            makeCurrent();
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }

    ~OsMesaContext() override {
        if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(context_);
    }

    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
            throw ContextError("prism: OSMesa backend: OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                               std::to_string(height_) + " buffer");
        loadGlFunctions(&osmesaLoader, "osmesa");
    }

    bool isCurrent() const override { return OSMesaGetCurrentContext() == context_; }
    int drawableWidth() const override { return width_; }
    int drawableHeight() const override { return height_; }

  private:
    int width_, height_;
    std::vector<unsigned char> buffer_;
    OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createOsMesaContext(const ContextOptions& options) {
    return std::make_unique<OsMesaContext>(options);
}

}  // namespace prism::gl::detail
