// Part of stage 5 (validation_scheduler.hpp), for programs compiled to SPIR-V (the Vulkan
// client, the spirv target): what a program's pipeline layout needs, read from its stages'
// SPIR-V through SPIRV-Cross's C API, so it is what the SPIR-V declares: every descriptor
// (set, binding, kind, array size with kUnboundedArray for `[]`, used or not), buffer blocks
// with their layout's size (the fixed part; a runtime array's stride apart) and members,
// push-constant members (a buffer_reference member as an 8-byte device address), the vertex
// stage's inputs at their own locations (used or not), the struct types of every block (for
// the generated C++ structs) and the specialisation constants (OpDecorate SpecId and
// OpSpecConstant*, read from the words). Stages are merged: one resource per set and binding.
//
//   r.spirv = {...};   // each stage's words
//   reflectSpirv(r);   // fills r's attributes, resources, push constants, spec constants
#pragma once

#include <cstdint>
#include <span>

#include "reflection.hpp"

namespace prism::shaderc {

// Fills `r.attributes`, `resources`, `pushConstants`, `pushConstantLayout` and
// `specConstants` from `r.spirv`, replacing what they held. Throws std::runtime_error for
// words SPIRV-Cross cannot parse.
void reflectSpirv(ProgramReflection& r);

// Adds the specialisation constants declared in `words` (one stage's SPIR-V) to `r`, once
// per constant id, keeping `r.specConstants` sorted by id.
void addSpecConstants(ProgramReflection& r, std::span<const std::uint32_t> words);

}  // namespace prism::shaderc
