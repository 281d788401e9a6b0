// Compute availability and counted dispatches (see prism/gl/compute.hpp).
#include "prism/gl/compute.hpp"

#include <atomic>
#include <string>

#include "prism/gl/gl.hpp"

namespace prism::gl {
namespace {

std::atomic<std::uint64_t> g_dispatches{0};

}  // namespace

int currentContextVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

bool computeAvailable() {
    return currentContextVersion() >= 43 && glDispatchCompute != nullptr && glMemoryBarrier != nullptr;
}

void requireCompute(std::string_view who) {
    const int version = currentContextVersion();
    if (version < 43)
        throw ComputeUnavailableError(
            std::string(who) + ": needs compute shaders (GL 4.3), but the current context is GL " +
            std::to_string(version / 10) + "." + std::to_string(version % 10) +
            "; create it with ContextOptions{.majorVersion = 4, .minorVersion = 3} (Mesa llvmpipe gives 4.5)");
    if (glDispatchCompute == nullptr || glMemoryBarrier == nullptr)
        throw ComputeUnavailableError(std::string(who) +
                                      ": the driver reports GL 4.3 but glDispatchCompute/glMemoryBarrier did not load");
}

std::array<std::uint32_t, 2> computeGroups(std::uint32_t count, std::uint32_t groupSize) {
    if (count == 0 || groupSize == 0) return {0, 0};
    const std::uint64_t groups = (std::uint64_t(count) + groupSize - 1) / groupSize;
    constexpr std::uint64_t kMaxX = 65535;
    if (groups <= kMaxX) return {static_cast<std::uint32_t>(groups), 1};
    return {static_cast<std::uint32_t>(kMaxX), static_cast<std::uint32_t>((groups + kMaxX - 1) / kMaxX)};
}

void dispatchInvocations(std::uint32_t count, std::uint32_t groupSize) {
    const auto groups = computeGroups(count, groupSize);
    dispatchGroups(groups[0], groups[1]);
}

void dispatchGroups(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    if (x == 0 || y == 0 || z == 0) return;
    glDispatchCompute(x, y, z);
    ++g_dispatches;
}

std::uint64_t computeDispatches() {
    return g_dispatches.load();
}

}  // namespace prism::gl
