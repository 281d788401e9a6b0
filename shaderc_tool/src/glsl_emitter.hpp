// --emit-glsl: writes each flattened, driver-safe stage as
// DIR/<shader>.<stage> (DIR/<shader>.<variant>.<stage> for shaders with variants),
// so the exact text a driver will see can be inspected or fed to other tools. A run with
// more targets than gl names the target in every file: DIR/<shader>[.<variant>].<target>.<stage>,
// for the shaders each target is produced for (es300 text: es300_target.hpp).
//
//   emitGlsl(options.emitGlslDir, catalog.data, {{Target::Gl, Target::Es300}, ...}, error);
#pragma once

#include <string>

#include "catalog_model.hpp"
#include "targets.hpp"

namespace prism::shaderc {

// DIR/<shader>[.<variant>]: the start of every file name of one variant's stages.
std::string emittedVariantBase(const std::string& dir, const CatalogShader& shader, const CatalogVariant& variant);

// `targets[s]`: the targets shader s is produced for (all of the run's: the run's targets).
bool emitGlsl(const std::string& dir, const CatalogData& catalog, const std::vector<Target>& runTargets,
              const std::vector<std::vector<Target>>& targets, std::string& error);

}  // namespace prism::shaderc
