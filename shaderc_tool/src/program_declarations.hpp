// Part of stage 3 (shader_inputs.hpp): the programs the command line declares with
// `--program NAME=FILE[,FILE...]` (CMake: prism_add_shaders(... PROGRAMS ...)). The files
// may have any names and lie anywhere; their stages are put in pipeline order whatever
// the argument's order, and one file may serve several programs (its compiled stage is
// then shared, validation_scheduler.hpp). NAME is any text without '/', '\', ',' or ':':
// its enumerator is mangleName(NAME) (module_naming.hpp), and name() returns NAME.
// Every error names the argument: `--program blur=a.vert,b.frg: error: ...`.
//
//   auto declared = declaredPrograms({"blur-h=fullscreen.vert,blur_h.frag"}, pairedByName, DiskReader());
//   // declared.programs[0].stages: {Vertex, "fullscreen.vert"}, {Fragment, "blur_h.frag"}
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "shader_inputs.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct DeclaredPrograms {
    std::vector<ShaderInput> programs;  // in argument order
    std::vector<Diagnostic> diagnostics;
    bool ioError = false;  // a named file that does not exist (exit status 2)
};

// `taken`: the programs paired by name in the input folders; a declaration may not reuse
// their names, nor another declaration's. `reader` says which files exist. The stages are
// checked as a pipeline under `rules` (checkCompleteness).
DeclaredPrograms declaredPrograms(const std::vector<std::string>& declarations, const std::vector<ShaderInput>& taken,
                                  const SourceReader& reader, const TargetRules& rules = {});

// The canonical paths of the files the declarations name: an input folder's file among
// them belongs to its declared program and is not paired by name.
std::set<std::string> filesNamedBy(const std::vector<std::string>& declarations, const SourceReader& reader);

}  // namespace prism::shaderc
