// Stage 2 of prism-shaderc: is there anything to do? The one record of "nothing changed",
// asked before any input is read, for every kind of run (a header, --emit-web, --emit-glsl,
// --emit-spirv, --emit-reflection, --check). A successful run writes it last, after its
// outputs: the fingerprint of the tool build that ran (tool_identity.hpp), the options that
// change outputs (output_options.hpp), every file it read and the listings of the searched
// folders (source_fingerprint.hpp), then each file it wrote with its size and modification
// time. The next run with the same record ends here, writing only the depfile and stamp,
// when the fingerprint is the same and every file written is still as it left it: an edit
// of any file read, a new module in an -I folder, another option or another tool build, or
// an output deleted or edited by hand, each make a full run. A --check that writes no file
// compares code signatures instead of texts (a comment edit passes without validating) and
// is recorded only when it found nothing at all, so its warnings are printed again.
// The record lives in the cache directory (validation_settings.hpp: --cache-dir, or next
// to --stamp), else beside the header (X.hpp.record); a run with neither keeps none.
//
//   if (auto unchanged = unchangedSinceLastRun(options, reader)) return write(unchanged->filesRead);
//   ... resolve, validate, writeOutputs ...
//   rememberRun(options, catalog.filesRead, sink, reader);
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "diagnostics.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct Unchanged {
    std::vector<std::string> filesRead;  // what the recorded run read, for the depfile
};

// The record's answer, before anything is read. Under --stats, says when a check ended here.
std::optional<Unchanged> unchangedSinceLastRun(const Options& options, const SourceReader& reader);

// After the outputs are written: records the run, or removes the record when the next run
// must be a full one (a check with diagnostics).
void rememberRun(const Options& options, const std::vector<std::string>& filesRead, const DiagnosticSink& sink,
                 const SourceReader& reader);

// Where the record lies: in the cache directory, else beside the header (X.hpp.record),
// else "" (no record).
std::string runRecordPath(const Options& options);

// Removes the record (a failed run).
void forgetRun(const Options& options);

}  // namespace prism::shaderc
