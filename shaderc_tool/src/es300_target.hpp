// Part of stage 5: the es300 target (GLSL ES 3.00 for WebGL2 and GLES 3.0; docs/targets.md).
// Its text is the resolved desktop stage with `#version 300 es` on line 1 and highp
// defaults for every type ES leaves without one (so `mediump` appears only where a module
// writes it); the module text, the loose uniforms (set by name) and the `#line` table stay.
// Every program a run asks es300 of is validated and linked by glslang as ES 3.00, so a
// desktop-only construct (an integer varying without `flat`, an implicit int->float
// conversion, `layout(binding)`) is an error at the module's own file:line:col, and then
// checked against the ES minimum limits (es300_limits.hpp).
//
//   sink.reportAll(validateEs300(options, catalog, contract));  // after the desktop validation passed
//   const ResolvedStage es = es300Stage(catalog.resolved[s][v][st]);  // what --emit-glsl writes
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "include_resolver.hpp"

namespace prism::shaderc {

// The es300 text of a flattened desktop stage (its `#version` on line 1).
std::string es300Text(const std::string& desktop);

// The es300 text of a resolved (desktop) stage; `files` and the line table are unchanged.
ResolvedStage es300Stage(const ResolvedStage& desktop);

// Validates, links and limit-checks every variant of every shader the run produces es300
// for (shader_targets.hpp), marking each one that passed (CatalogVariant::es300); diagnostics
// in catalogue order.
std::vector<Diagnostic> validateEs300(const Options& options, ResolvedCatalog& catalog, const Contract& contract);

}  // namespace prism::shaderc
