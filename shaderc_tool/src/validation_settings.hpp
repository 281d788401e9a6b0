// The validation cache's pack name and how its counts are printed (where the cache lives,
// validationCacheDir, is output_options.hpp's: the run record lies there too).
//
//   ValidationCache cache(validationCacheDir(options), catalogueCacheKey(options));
#pragma once

#include <iosfwd>
#include <string>

#include "args.hpp"
#include "output_options.hpp"
#include "validation_scheduler.hpp"

namespace prism::shaderc {

// Names the catalogue's pack in the cache directory: a hash of the options that choose
// its programs and how they are checked (output_options.hpp's kValidationPack rows: inputs,
// -I, -D, --contract, --variant, --program, --glsl-version, --client, --target, --base-dir,
// --warn-undocumented-modules), so a `--check` and the build's `-o` run of one catalogue
// share it, and catalogues sharing a directory do not overwrite each other's.
std::string catalogueCacheKey(const Options& options);

// "prism-shaderc: resolved 304 stages with 20 runs of glslang's preprocessor (294 shared
// another run) in 35.0 ms, 25.0 ms of it glslang's built-in tables" (wall clock).
void printResolutionStats(std::ostream& out, const ResolvedCatalog& catalog);

// "prism-shaderc: validated 12 of 152 programs (140 shared a token stream, 0 from the cache;
// 13 stages parsed) in 9.0 ms".
void printValidationStats(std::ostream& out, const ValidationStats& stats);

}  // namespace prism::shaderc
