// Stage 6 of prism-shaderc: the outputs. First what the catalogue generates: writeOutputs
// loops over the registered output generators (output_generator.hpp: the header and its data
// file, the --emit-spirv files, the web catalogue, the reflection JSON, the --emit-glsl
// texts), and writes the files of each that the options ask for, each only when its bytes
// changed (output_file.hpp). Then the build system's files, written by every successful run,
// a no-op included: the depfile (depfile.hpp) and the --stamp. Each returns "" or the error
// to report.
//
//   if (auto error = writeOutputs(options, catalog); !error.empty()) ... // exit 2
//   if (auto error = writeBuildSystemFiles(options, catalog.filesRead); !error.empty()) ...
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"

namespace prism::shaderc {

// Every generator's files, in the list's order. When a write fails, the files of that
// generator that this run created are removed (a new header never stands without its data file).
std::string writeOutputs(const Options& options, const ResolvedCatalog& catalog);

// The depfile (listing `filesRead`) and the stamp, where the options ask for them.
std::string writeBuildSystemFiles(const Options& options, const std::vector<std::string>& filesRead);

}  // namespace prism::shaderc
