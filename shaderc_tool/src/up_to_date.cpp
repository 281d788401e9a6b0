// The no-op decision of prism-shaderc (see up_to_date.hpp).
#include "up_to_date.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include "clean_check.hpp"
#include "data_file_records.hpp"
#include "generated_format.hpp"
#include "output_file.hpp"
#include "source_fingerprint.hpp"
#include "tool_identity.hpp"

namespace prism::shaderc {
namespace {

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The end of `path`, where the data file keeps its sources record: reading only that keeps
// the no-op flat in the catalogue's size. The whole file when the record starts earlier.
std::string readRecord(const std::string& path) {
    constexpr auto kTail = static_cast<std::streamoff>(format::kRecordTailBytes);
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : 0;
    if (size <= kTail) return readWholeFile(path);
    in.seekg(size - kTail);
    std::string tail(static_cast<std::size_t>(kTail), '\0');
    in.read(tail.data(), kTail);
    return tail.find("\n" + std::string(format::kSourcesRecordStart)) != std::string::npos ? tail : readWholeFile(path);
}

// Records 1 and 3 belong to runs that write a header and nothing else.
bool writesHeaderOnly(const Options& o) {
    return !o.checkOnly && !o.output.empty() && o.emitGlslDir.empty() && o.emitSpirvDir.empty() && o.emitWeb.empty() &&
           o.emitReflection.empty();
}

// The outputs on disk were written by this build of the tool: a rebuilt prism-shaderc must
// not trust what an older build generated. Its identity is in the stamp (tool_identity.hpp),
// not in the outputs; a run without --stamp (by hand) has only the outputs to go by.
bool writtenByThisTool(const Options& o) {
    return o.stamp.empty() || readWholeFile(o.stamp) == stampText();
}

void removeStaleOutputTemps(const Options& o) {  // nothing to write, but a killed run may have left temp files
    removeStaleTemps(o.output);
    removeStaleTemps(dataPathFor(o.output));
}

}  // namespace

std::optional<Unchanged> unchangedBeforeResolution(const Options& o, const SourceReader& reader) {
    if (writesHeaderOnly(o) && writtenByThisTool(o))
        if (const auto record = readRecord(dataPathFor(o.output)); headerMatchesData(readWholeFile(o.output), record))
            if (auto files = unchangedSources(o, record, reader)) {
                removeStaleOutputTemps(o);
                return Unchanged{std::move(*files)};
            }
    if (auto files = unchangedSinceCleanCheck(o, reader)) {
        if (o.printStats) std::cerr << "prism-shaderc: no code changed since the last clean check; nothing validated\n";
        return Unchanged{std::move(*files)};
    }
    return std::nullopt;
}

void fillRecords(const Options& o, ResolvedCatalog& catalog, const SourceReader& reader) {
    if (o.checkOnly || o.output.empty()) return;
    catalog.data.sourcesBlock = sourcesBlock(recordSources(o, catalog.filesRead, reader));
    catalog.data.fingerprint = fingerprint(catalog);
}

// The data file records the fingerprint and is written after the header, so a run killed
// between the two leaves a stale record that the next run does not trust.
// The header must be the one the data file records (not deleted, edited or left stale).
bool outputsAreCurrent(const Options& o, const ResolvedCatalog& catalog) {
    if (!writesHeaderOnly(o) || !writtenByThisTool(o)) return false;
    const auto data = readWholeFile(dataPathFor(o.output));
    if (!headerMatchesData(readWholeFile(o.output), data) || recordedFingerprint(data) != catalog.data.fingerprint)
        return false;
    removeStaleOutputTemps(o);
    return true;
}

void rememberCheckOutcome(const Options& o, const ResolvedCatalog& catalog, const DiagnosticSink& sink,
                          const SourceReader& reader) {
    if (sink.diagnostics().empty())
        recordCleanCheck(o, catalog.filesRead, reader);
    else
        forgetCleanCheck(o);
}

}  // namespace prism::shaderc
