// The files of --emit-glsl and --emit-spirv (their generators: generator_glsl.cpp,
// generator_spirv.cpp), path and bytes. --emit-glsl: each flattened, driver-safe stage as
// DIR/<shader>.<stage> (DIR/<shader>.<variant>.<stage> for shaders with variants),
// so the exact text a driver will see can be inspected or fed to other tools. A run with
// more targets than gl names the target in every file: DIR/<shader>[.<variant>].<target>.<stage>,
// for the shaders each target is produced for (es300 text: es300_target.hpp).
// --emit-spirv: each stage's SPIR-V (the Vulkan client's or the spirv target's) under the
// names of a gl-only run with `.spv` appended, the words as little-endian bytes, as
// spirv-val, spirv-dis and Vulkan loaders read them: e.g. DIR/blur.FOG-1.frag.spv.
//
//   std::vector<std::vector<Target>> perShader = {{Target::Gl, Target::Es300}, {Target::Gl}};
//   auto texts = glslFiles(options.emitGlslDir, catalog.data, {Target::Gl, Target::Es300}, perShader);
//   auto modules = spirvFiles("build/spv", catalog.data);  // e.g. {"build/spv/blur.frag.spv", bytes}
#pragma once

#include <string>
#include <vector>

#include "catalog_model.hpp"
#include "output_generator.hpp"
#include "targets.hpp"

namespace prism::shaderc {

// `targets[s]`: the targets shader s is produced for, among the run's `runTargets`.
std::vector<GeneratedFile> glslFiles(const std::string& dir, const CatalogData& catalog,
                                     const std::vector<Target>& runTargets,
                                     const std::vector<std::vector<Target>>& targets);
// Every stage's SPIR-V (CatalogVariant::spirv), the words as little-endian bytes.
std::vector<GeneratedFile> spirvFiles(const std::string& dir, const CatalogData& catalog);

// The name --emit-spirv gives a stage's SPIR-V inside its DIR: <shader>[.<variant>].<stage>.spv.
std::string spirvFileName(const CatalogShader& s, const CatalogVariant& v, catalog::Stage stage);

}  // namespace prism::shaderc
