// Part of stage 5: which targets each shader of a resolved catalogue serves, and the
// refusals of what a target cannot do (docs/targets.md).
// - A stage's `#pragma prism targets gl spirv` lists the only targets it serves; a shader
//   serves the targets every stage of every variant serves (no pragma: all of them).
// - A run's target a shader does not serve leaves the shader out of that target's
//   outputs, quietly: that is what the pragma is for. Naming the shader in --variant
//   asks for it explicitly, so there it is an error.
// - A shader that is to serve es300 but has a geometry or compute stage is an error
//   naming the shader, the stage file and the target, with the pragma that would opt out.
//
//   sink.reportAll(checkShaderTargets(options, catalog));
//   if (servesTarget(catalog, shader, Target::Es300)) ...
#pragma once

#include <cstddef>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "targets.hpp"

namespace prism::shaderc {

struct ShaderTargets {
    std::vector<Target> targets;                 // the targets the shader serves
    const TargetsPragma* declaration = nullptr;  // the first pragma that narrowed them, if any
};

ShaderTargets shaderTargets(const ResolvedCatalog& catalog, std::size_t shader);

// The run asks for `target` and the shader serves it.
bool producedFor(const Options& options, const ResolvedCatalog& catalog, std::size_t shader, Target target);

std::vector<Diagnostic> checkShaderTargets(const Options& options, const ResolvedCatalog& catalog);

// "'phong' (variant FOG=1)", or "'phong'" for a shader of one variant: a program in a
// target's messages.
std::string targetProgramName(const ResolvedCatalog& catalog, std::size_t shader, std::size_t variant);

// Adds to every error of a target's program the note saying which target and program
// (`what`: "for target es300 (GLSL ES 3.00) in program 'phong' ...").
void noteTarget(std::vector<Diagnostic>& diagnostics, const std::string& what);

}  // namespace prism::shaderc
