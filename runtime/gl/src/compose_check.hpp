// Run-time composition's checks, done by the shader tool's own stages (prism/shaderc/build_step.hpp):
// glslang compilation and linking, the cross-stage interface check and the contract
// check, with diagnostics at each module's file:line. Internal to prism_gl.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/gl/compose.hpp"
#include "prism/gl/program.hpp"
#include "prism/shaderc/build_step.hpp"

namespace prism::gl::detail {

// GCC-style diagnostics (`path:line:col: error: message`) for the composed stages; empty
// when the program is valid. Warnings are included only when there is an error.
// `contractFiles` name the catalogue's contract in its diagnostics.
std::vector<std::string> checkComposedSources(const catalog::Catalog& catalog, const ProgramSources& sources,
                                              std::span<const std::string> contractFiles);

// `heading` and then the build step's messages, each also one of its diagnostics: how
// composition and module libraries report what the build step's stages found.
CompositionError compositionError(const std::string& heading, std::span<const shaderc::Message> messages);

}  // namespace prism::gl::detail
