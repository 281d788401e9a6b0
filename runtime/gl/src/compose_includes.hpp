// The #include lines of a composed stage's own source, resolved as the build step resolves
// them (prism/shaderc/build_step.hpp's scanModule): the including file's folder first, then
// the catalogue's module roots, with the stage's defines deciding which lines are active.
// Each file found must be a module of the catalogue; it joins the stage's modules. Internal
// to prism_gl.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"

namespace prism::gl::detail {

// The ids of the modules `source` (named `sourceName`) includes, in order; throws
// CompositionError with the build step's `path:line:col: error: ...` diagnostics when an
// include is missing or names a file that is not a module of `catalog`.
std::vector<std::uint32_t> includedModules(const catalog::Catalog& catalog, const std::string& sourceName,
                                           std::string_view source, std::span<const catalog::Define> defines);

}  // namespace prism::gl::detail
