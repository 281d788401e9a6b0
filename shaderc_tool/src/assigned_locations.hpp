// The spirv target's locations after glslang assigned them (TProgram::mapIO, relaxed
// rules). glslang 12 does not keep its automatic locations clear of the explicit ones of
// the same interface: a stage that declares `layout(location = 0) out vec3 a;` and then
// `out vec3 b;` gets both at location 0, and SPIRV-Tools rejects the module with a message
// that names no line. This check says it first, at the declaration glslang placed, with a
// note at the one that holds the location by its own layout.
//
//   auto before = interfacesOf(shaders);  // as written: explicit locations only
//   program.mapIO();
//   auto messages = checkAssignedLocations(before, interfacesOf(shaders), locate);
#pragma once

#include <vector>

#include "diagnostics.hpp"
#include "interface_check.hpp"
#include "stage_interface.hpp"

namespace prism::shaderc {

// `before` and `after` list the same stages' variables in the same order (one extraction
// before mapIO, one after). One error per variable glslang placed over another's locations.
std::vector<Diagnostic> checkAssignedLocations(const std::vector<StageInterface>& before,
                                               const std::vector<StageInterface>& after, const SourceLocator& locate);

}  // namespace prism::shaderc
