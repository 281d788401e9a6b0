// Stage 6 of prism-shaderc: the outputs. First what the catalogue generates: the header
// and its data file (header_writer.hpp, data_writer.hpp), each written only when its text
// changed (output_file.hpp), the flattened stages of --emit-glsl (glsl_emitter.hpp), the web
// catalogue of --emit-web (web_writer.hpp) and the reflection JSON of --emit-reflection
// (reflection_writer.hpp).
// Then the build system's files, written by every successful run, a no-op included: the
// depfile (depfile.hpp) and the --stamp. Each returns "" or the error to report.
//
//   if (auto error = writeOutputs(options, catalog); !error.empty()) ... // exit 2
//   if (auto error = writeBuildSystemFiles(options, catalog.filesRead); !error.empty()) ...
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"

namespace prism::shaderc {

// The header, data file and --emit-glsl files. On failure a header this run created is removed.
std::string writeOutputs(const Options& options, const ResolvedCatalog& catalog);

// The depfile (listing `filesRead`) and the stamp, where the options ask for them.
std::string writeBuildSystemFiles(const Options& options, const std::vector<std::string>& filesRead);

}  // namespace prism::shaderc
