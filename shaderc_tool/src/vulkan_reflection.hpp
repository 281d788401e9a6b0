// Part of stage 5 (validation_scheduler.hpp), for programs compiled to SPIR-V (the Vulkan
// client, the spirv target): what a Vulkan program's pipeline layout needs, from a linked
// glslang program (descriptors with set, binding, kind and size, uniform blocks with their
// members' offsets; push-constant members with offsets; vertex inputs with their own
// locations) and from its stages' SPIR-V (specialisation constants: glslang's reflection
// does not list them, so OpDecorate SpecId and OpSpecConstant* are read from the words).
//
//   ProgramReflection r = reflectVulkanProgram(program);   // program linked for Vulkan
//   addSpecConstants(r, words);                            // for each stage's SPIR-V
#pragma once

#include <cstdint>
#include <span>

#include "reflection.hpp"

namespace glslang {
class TProgram;
}

namespace prism::shaderc {

// `program` must be linked, with no reflection built yet.
ProgramReflection reflectVulkanProgram(glslang::TProgram& program);

// Adds the specialisation constants declared in `words` (one stage's SPIR-V) to `r`, once
// per constant id, keeping `r.specConstants` sorted by id.
void addSpecConstants(ProgramReflection& r, std::span<const std::uint32_t> words);

}  // namespace prism::shaderc
