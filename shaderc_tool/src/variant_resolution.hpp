// Stage 2b of prism-shaderc: resolves every stage of every chosen variant of a shader
// (include_resolver.hpp) on `jobs` threads (the readers cache files behind a mutex and
// glslang's preprocessor is thread-safe per TShader).
//
// Variants share what cannot differ: glslang's preprocessing is a function of the texts
// it reads and the macros' values, and a macro's value matters only where its name is
// met. So a variant whose defines differ from an already resolved one only in macros
// whose names appear in none of the files that run read (nor in any macro's value), with
// no `##` token pasting in them, gets that result with its own #define lines: the same
// files, include decisions and token stream. Any other variant runs glslang itself.
// PRISM_SHADERC_NO_VARIANT_SHARING=1 turns sharing off (tests compare both).
//
//   auto results = resolveVariants(stagePaths, baseOptions, choices, reader, jobs);
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
                                                        const SourceReader& reader, int jobs);

}  // namespace prism::shaderc
