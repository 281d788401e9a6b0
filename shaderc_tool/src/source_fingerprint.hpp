// The fingerprint of what a run read: the options that change the outputs
// (output_options.hpp), every file read (relative to --base-dir) and the listings of the -I
// directories and input folders. Two users: the one record of "nothing changed"
// (run_record.hpp), and the sources block that ends the data file, printed since layout 3
// and kept byte for byte (the golden files), which nothing reads back any more.
//
//   record.key = sourcesFingerprint(options, embeddedNames(options, filesRead), reader, ContentKey::Text,
//                                   RecordScope::Run);
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

// What the fingerprint takes of each recorded file: its whole text (the outputs embed
// it), or its code signature (code_signature.hpp: what glslang's tokens depend on, all a
// --check without emitted files depends on).
enum class ContentKey { Text, Code };

// Run: the run record, which also names the tool build and hashes every option that
// changes outputs. DataFile: the data file's printed block, with the rows it always had.
enum class RecordScope { Run, DataFile };

// The files read as embedded: relative to --base-dir where possible, sorted, unique.
std::vector<std::string> embeddedNames(const Options& options, const std::vector<std::string>& filesRead);

std::string sourcesFingerprint(const Options& options, const std::vector<std::string>& embedded,
                               const SourceReader& reader, ContentKey key, RecordScope scope);

struct SourcesRecord {
    std::string fingerprint;
    std::vector<std::string> files;  // as embedded
};

// The data file's sources block of a run that read `filesRead` (paths as read).
SourcesRecord recordSources(const Options& options, const std::vector<std::string>& filesRead,
                            const SourceReader& reader);
std::string sourcesBlock(const SourcesRecord& record);

}  // namespace prism::shaderc
