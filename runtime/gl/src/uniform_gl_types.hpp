// What prism_gl's uniform code asks of a GL type enum, in one place for the setters'
// type check (program_uniforms.cpp) and the unset-uniform report (program_unset.cpp).
#pragma once

#include <cstdint>

namespace prism::gl::detail {

// Every sampler type of GL 4.3 core (set with a texture unit).
bool isSamplerType(std::uint32_t glType);

}  // namespace prism::gl::detail
