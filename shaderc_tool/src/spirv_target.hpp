// Part of stage 5: the spirv target (docs/targets.md). Every program the run produces spirv
// for is compiled from its desktop text through the Vulkan client's path (validator.hpp:
// glslang's SPIR-V generator, SPIRV-Tools on every stage, vulkan_reflection.hpp) for
// Vulkan 1.1, with glslang's relaxed Vulkan rules: the loose uniforms of each stage are
// packed into one std140 block (gl_DefaultUniformBlock), and glslang assigns locations and
// bindings, deterministically, in declaration order. Messages land at the module's own
// file:line. The reflection (block set/binding/size with member offsets, samplers, vertex
// input locations) is enough for a Vulkan application to fill the block without another
// reflection library. A Vulkan-client catalogue has no spirv target: its output is SPIR-V,
// its validated `reflection`, which buildSpirvTarget puts where every output reads a
// variant's SPIR-V (CatalogVariant::spirv): one route to it, whoever made it.
//
//   sink.reportAll(buildSpirvTarget(options, catalog, contract));
//   if (const auto& r = catalog.data.shaders[s].variants[v].spirv) use(r->spirv[0].words, r->resources);
#pragma once

#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "spirv_codegen.hpp"

namespace prism::shaderc {

// Fills `spirv` of every variant the run has SPIR-V for; returns the diagnostics.
std::vector<Diagnostic> buildSpirvTarget(const Options& options, ResolvedCatalog& catalog, const Contract& contract);

}  // namespace prism::shaderc
