// Stage 3 of prism-shaderc: compiles every stage of one variant with glslang, links the
// program, runs the cross-stage interface check and the contract check, and maps each
// glslang message back to the module's own file:line (with its "included from" chain).
#pragma once

#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "include_resolver.hpp"
#include "reflection.hpp"

namespace prism::shaderc {

struct StageToValidate {
    catalog::Stage stage;
    std::string path;  // the stage file, for errors without a line
    ResolvedStage resolved;
};

struct ValidatedVariant {
    bool ok = false;
    ProgramReflection reflection;
    std::vector<Diagnostic> diagnostics;
};

// Call once per process before any validateProgram (thread-safe afterwards).
void initializeValidator();
void finalizeValidator();

// Thread-safe: each call uses its own glslang objects.
ValidatedVariant validateProgram(const std::vector<StageToValidate>& stages, const Contract& contract);

}  // namespace prism::shaderc
