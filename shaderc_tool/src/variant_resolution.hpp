// Part of stage 4 (catalog_builder.hpp): resolves every stage of every chosen variant of a
// shader (include_resolver.hpp) on `jobs` threads (the readers cache files behind a mutex
// and glslang's preprocessor is thread-safe per TShader).
//
// Variants share what cannot differ: the flattened text is the files glslang enters and
// the directives it reaches, and only structural macros (structural_macros.hpp) can
// change those. So a variant whose defines differ from a run made for real only in
// macros that are structural in none of the files that run read gets that result with
// its own #define lines. The runs made with the base options (no variant defines), which
// found the variant axes, are the first such runs; then one variant per group of like
// structural values runs glslang; any variant still left runs it on its own.
// With `share` false every variant runs glslang (the reference that tests and the
// variant_sharing fuzzer compare with; prism-shaderc does so with --no-variant-sharing).
// Last, each stage gets its validation key (validation_key.hpp).
//
//   auto results = resolveVariants(stagePaths, baseOptions, choices, reader, jobs, baseRuns, true);
//   // results[variant][stage], in the order of `choices` and `stagePaths`
#pragma once

#include <string>
#include <vector>

#include "include_resolver.hpp"
#include "variants.hpp"

namespace prism::shaderc {

std::vector<std::vector<ResolveResult>> resolveVariants(const std::vector<std::string>& stagePaths,
                                                        const ResolveOptions& base,
                                                        const std::vector<VariantChoice>& choices,
                                                        const SourceReader& reader, int jobs,
                                                        const std::vector<ResolveResult>& baseRuns, bool share);

}  // namespace prism::shaderc
