// A composed stage's own source resolved as the build step resolves a stage
// (prism/shaderc/build_step.hpp's resolveStage): its #include lines found in the build
// step's search order (the including file's folder first, then the module roots, the -D
// macros deciding which lines are active), include cycles and #version conflicts with
// the modules it includes reported as prism-shaderc reports them. Each file it reaches
// must be a module of the catalogue; it joins the stage's modules. Internal to prism_gl.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/catalog/source_tree.hpp"

namespace prism::gl::detail {

// Where module `m` lies: its catalogue path, or with the catalogue's source tree the file
// the build step read (the base dir or its -I directory joined with the path).
std::string modulePathIn(const catalog::Module& m, const catalog::SourceTree* tree);

// The ids of the modules `source` (named `sourceName`) includes, directly or not, in the
// order the resolver read them; throws CompositionError with the build step's
// `path:line:col: error: ...` diagnostics when an include is missing, closes a cycle,
// asks for another #version, or names a file that is not a module of `catalog`. `tree`
// (may be null) places the modules and the -I directories where the build step had them.
std::vector<std::uint32_t> includedModules(const catalog::Catalog& catalog, const catalog::SourceTree* tree,
                                           const std::string& sourceName, std::string_view source,
                                           std::span<const catalog::Define> defines);

}  // namespace prism::gl::detail
