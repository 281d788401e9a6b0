// GL_TIME_ELAPSED frame timing with a CPU fallback (gpu_timer.hpp).
#include "gpu_timer.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "prism/gl/gl.hpp"

namespace prism::viewer {

namespace {
bool hasTimerQuery() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major > 3 || (major == 3 && minor >= 3)) return true;  // core since GL 3.3
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
        const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (e && std::strcmp(e, "GL_ARB_timer_query") == 0) return true;
    }
    return false;
}

// llvmpipe and the other Mesa software rasterisers draw on the CPU when the frame is
// flushed, outside the query's begin and end: their elapsed time reads near zero.
bool softwareRenderer() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string renderer = r ? r : "";
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos ||
           renderer.find("swrast") != std::string::npos;
}
}  // namespace

FrameTimer::FrameTimer() {
    const char* force = std::getenv("PRISM_VIEWER_CPU_TIMER");
    gpu_ = !(force && *force == '1') && !softwareRenderer() && hasTimerQuery();
    if (gpu_)
        for (auto& q : queries_) q = gl::Query::create();
}

void FrameTimer::begin() {
    start_ = std::chrono::steady_clock::now();
    if (!gpu_) return;
    if (pending_[current_]) {  // the query of two frames ago: done by now, or wait for it
        GLuint64 ns = 0;
        glGetQueryObjectui64v(queries_[current_].id(), GL_QUERY_RESULT, &ns);
        lastMs_ = static_cast<double>(ns) * 1e-6;
        pending_[current_] = false;
    }
    glBeginQuery(GL_TIME_ELAPSED, queries_[current_].id());
}

void FrameTimer::end() {
    if (gpu_) {
        glEndQuery(GL_TIME_ELAPSED);
        pending_[current_] = true;
        current_ = 1 - current_;
        return;
    }
    glFinish();
    lastMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace prism::viewer
