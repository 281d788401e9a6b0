// Part of stage 5: the spirv target (docs/targets.md). Every program the run produces spirv
// for is compiled from its desktop text for Vulkan 1.1 with glslang's relaxed Vulkan rules:
// the loose uniforms of each stage are packed into one std140 block (gl_DefaultUniformBlock),
// and glslang assigns locations and bindings, deterministically, in declaration order.
// Messages land at the module's own file:line (validator.hpp). Each stage's SPIR-V goes
// through SPIRV-Tools' validator (spirv_codegen.hpp) and the program is reflected: block
// set/binding/size with member offsets, samplers, vertex input locations, which is enough
// for a Vulkan application to fill the block without another reflection library.
//
//   sink.reportAll(buildSpirvTarget(options, catalog, contract));
//   if (const auto& p = catalog.data.shaders[s].variants[v].spirv) use(p->stages[0].words, p->reflection.blocks);
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "spirv_codegen.hpp"
#include "spirv_program.hpp"

namespace prism::shaderc {

inline constexpr SpirvEnv kSpirvTargetEnv = SpirvEnv::Vulkan1_1;

// Fills `spirv` of every variant the run produces spirv for; returns the diagnostics.
std::vector<Diagnostic> buildSpirvTarget(const Options& options, ResolvedCatalog& catalog, const Contract& contract);

}  // namespace prism::shaderc
