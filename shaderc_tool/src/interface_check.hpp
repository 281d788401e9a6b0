// The cross-stage interface check that glslang 12 lacks: every input of a stage after
// the vertex stage must match an output of the previous stage, as GL links them (the same
// explicit location whatever the names, else the same name), in type, array size,
// interpolation qualifier (flat / smooth / noperspective), `patch` and `perprimitiveEXT`.
// The per-vertex arrays of tesc, tese and geom inputs and of tesc and mesh outputs (a mesh
// stage's per-primitive outputs are arrays over its primitives) are compared element-wise.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "stage_interface.hpp"

namespace prism::shaderc {

// Maps (index of the stage in `stages`, source number) to a file:line location.
struct SourceLocator {
    std::function<std::string(std::size_t stage, std::uint32_t sourceNumber)> path;
    std::function<std::vector<IncludeSite>(std::size_t stage, std::uint32_t sourceNumber)> chain;
};

std::vector<Diagnostic> checkStageInterfaces(const std::vector<StageInterface>& stages, const SourceLocator& locate);

Diagnostic diagnosticAt(const SourceLocator& locate, std::size_t stage, const InterfaceVariable& v, Severity severity,
                        std::string message);

}  // namespace prism::shaderc
