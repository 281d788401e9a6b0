// Where the stages of a Vulkan pipeline meet besides their stage interfaces: descriptors
// by set and binding (a pipeline layout has one descriptor per set/binding, whatever the
// blocks are called), and a ray-tracing program's payloads, hit attributes and callable
// data by location. Vulkan links nothing by block name, so blocks that only share a name
// are no error here. Works on the plain structs of stage_interface.hpp.
//
//   auto errors = checkDescriptorBindings(interfaces, locate);  // each error has a note at the other stage
//   auto more = checkRayTracingData(interfaces, locate);
#pragma once

#include <vector>

#include "diagnostics.hpp"
#include "interface_check.hpp"
#include "stage_interface.hpp"

namespace prism::shaderc {

// Two stages with incompatible resources on one set and binding (a uniform buffer and a
// storage buffer, a sampler2D and a sampler3D, different array sizes): an error at the
// later stage's declaration with a note at the earlier one's.
std::vector<Diagnostic> checkDescriptorBindings(const std::vector<StageInterface>& stages, const SourceLocator& locate);

// A payload (rayPayloadEXT / rayPayloadInEXT) or callable data location declared with
// different types in two stages, or hit attributes of different types: an error at the
// later declaration with a note at the earlier one.
std::vector<Diagnostic> checkRayTracingData(const std::vector<StageInterface>& stages, const SourceLocator& locate);

}  // namespace prism::shaderc
