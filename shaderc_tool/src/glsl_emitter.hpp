// --emit-glsl: writes each flattened, driver-safe stage as
// DIR/<shader>.<stage> (DIR/<shader>.<variant>.<stage> for shaders with variants),
// so the exact text a driver will see can be inspected or fed to other tools.
// --emit-spirv (Vulkan client): the same names with `.spv` appended, each the stage's
// SPIR-V words as bytes (little-endian), e.g. DIR/blur.FOG-1.frag.spv.
//
//   if (!emitGlsl("build/glsl", catalog, error)) return error;
#pragma once

#include <string>

#include "catalog_model.hpp"

namespace prism::shaderc {

bool emitGlsl(const std::string& dir, const CatalogData& catalog, std::string& error);
bool emitSpirv(const std::string& dir, const CatalogData& catalog, std::string& error);

}  // namespace prism::shaderc
