// Stage 2 of prism-shaderc: is there anything to do? The one place that lets a run skip
// work because nothing it depends on changed. Its records answer in this order:
//   1. The sources record (source_fingerprint.hpp), at the end of the data file. Asked
//      first, before any input is read, by a run that writes a header (-o without
//      --emit-glsl): when the header is the one the data file records (its hash) and the
//      files the last run read, the options that change the outputs and the listings of
//      the -I and input folders are all as recorded, the run ends here.
//   2. The clean-check record (clean_check.hpp), in the cache directory. Asked instead by
//      --check (without --revalidate, --emit-glsl): when the last check found nothing and
//      every file it read has the same code signature, the check passes here. Written by
//      a full check that found nothing, removed by one that found something
//      (rememberCheckOutcome).
//   3. The inputs fingerprint (catalog_builder.hpp's fingerprint()), in the data file's
//      banner. Asked after resolution, by the runs of 1: it covers everything the outputs
//      print, the new sources record included, so it answers where record 1 could not be
//      read back (a record that lists no file, or one damaged by hand) but the outputs
//      would be the same.
//   4. The validation cache (validation_cache.hpp), asked inside stage 5 for each program
//      and not for the run: a program whose token stream passed before is not validated.
// Records 1 and 2 answer only for the build of the tool that wrote them (tool_identity.hpp):
// record 2 names it, and with --stamp the stamp names the build that wrote the outputs
// (records 1 and 3), so a rebuilt prism-shaderc regenerates what an older one left.
// When 1, 2 or 3 answers, only the depfile and stamp are written (stage 6).
//
//   if (auto unchanged = unchangedBeforeResolution(options, reader)) return write(unchanged->filesRead);
//   auto catalog = resolveCatalog(...);
//   fillRecords(options, catalog, reader);
//   if (!errors && outputsAreCurrent(options, catalog)) return write(catalog.filesRead);
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "diagnostics.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct Unchanged {
    std::vector<std::string> filesRead;  // what the recorded run read, for the depfile
};

// Records 1 and 2, before anything is read. Under --stats, says when record 2 answered.
std::optional<Unchanged> unchangedBeforeResolution(const Options& options, const SourceReader& reader);

// Sets what the data file will record (the sources record and the inputs fingerprint)
// when the run writes a header.
void fillRecords(const Options& options, ResolvedCatalog& catalog, const SourceReader& reader);

// Record 3: true when the header and data file on disk are those this catalogue writes.
bool outputsAreCurrent(const Options& options, const ResolvedCatalog& catalog);

// Record 2 after a full check: written when it found nothing, else removed.
void rememberCheckOutcome(const Options& options, const ResolvedCatalog& catalog, const DiagnosticSink& sink,
                          const SourceReader& reader);

}  // namespace prism::shaderc
