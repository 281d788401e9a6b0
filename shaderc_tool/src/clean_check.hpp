// The clean-check record of stage 2 (up_to_date.hpp), the shortcut of --check. After a
// check that found nothing at all (no error, no warning), the run records every file it
// read with its code signature (code_signature.hpp) in the validation cache directory. A
// later --check of the same catalogue whose files all have the same signatures, the same -I
// and input folder listings and the same options sees the same token streams, so it ends
// there, passing, without resolving or validating: a comment or layout edit costs a few
// milliseconds. Any code edit, a new file in a searched folder, or a check with diagnostics
// (which must be printed again) runs the full check. Only with a cache directory
// (--cache-dir, or the default next to --stamp).
//
//   if (auto files = unchangedSinceCleanCheck(options, reader)) ... // passed; *files for the depfile
//   recordCleanCheck(options, catalog.filesRead, reader);             // after a check without diagnostics
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

std::optional<std::vector<std::string>> unchangedSinceCleanCheck(const Options& options, const SourceReader& reader);

// Writes the record (atomically); false, with a warning on stderr, when it cannot.
bool recordCleanCheck(const Options& options, const std::vector<std::string>& filesRead, const SourceReader& reader);

// Removes the record: a check that found something must run in full next time.
void forgetCleanCheck(const Options& options);

}  // namespace prism::shaderc
