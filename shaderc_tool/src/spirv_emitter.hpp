// --emit-spirv: writes each stage's SPIR-V of the spirv target as
// DIR/<shader>[.<variant>].<stage>.spv (the names of --emit-glsl, glsl_emitter.hpp), the
// words in the host's byte order as spirv-val, spirv-dis and Vulkan loaders read them.
//
//   if (!emitSpirv(options.emitSpirvDir, catalog.data, error)) ...  // exit 2
#pragma once

#include <string>

#include "catalog_model.hpp"

namespace prism::shaderc {

bool emitSpirv(const std::string& dir, const CatalogData& catalog, std::string& error);

}  // namespace prism::shaderc
