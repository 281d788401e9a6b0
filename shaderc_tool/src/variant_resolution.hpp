// Stage 2b of prism-shaderc: resolves every stage of every chosen variant of a shader
// (include_resolver.hpp) on `jobs` threads. Each (variant, stage) is independent: the
// readers cache files behind a mutex and glslang's preprocessor is thread-safe per
// TShader.
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
