// The rain system's counted compute dispatches (see prism/rain/compute.hpp).
#include "prism/rain/compute.hpp"

#include "prism/gl/gl.hpp"
#include "prism/rain/gl_resources.hpp"

namespace prism::rain {

void ComputeFunctions::dispatch(std::uint32_t count) const {
    if (count == 0) return;
    gl::dispatchInvocations(count, kComputeGroupSize);
    detail::countDispatch();
}

void ComputeFunctions::barrier(unsigned bits) const {
    glMemoryBarrier(bits);
}

bool computeAvailable() {
    return gl::computeAvailable();
}

ComputeFunctions loadComputeFunctions() {
    gl::requireCompute("rain: the GPU particle update");
    return {};
}

}  // namespace prism::rain
