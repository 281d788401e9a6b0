// The sources record of stage 2 (up_to_date.hpp), the cheap no-op check. The data file
// records, at its end, every file the run that wrote it read (relative to --base-dir) and a
// fingerprint of the tool version, the options that change the output (never --depfile,
// --stamp or --emit-glsl), those files' contents and the listings of the -I directories and
// input folders. When all of that is unchanged, nothing the outputs depend on changed, and
// the run ends before any resolution or glslang call.
//
//   if (auto files = unchangedSources(options, dataText, reader)) ... // no-op; *files for the depfile
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

// What the fingerprint takes of each recorded file: its whole text (the outputs embed
// it), or its code signature (code_signature.hpp: what glslang's tokens depend on; the
// clean-check shortcut, clean_check.hpp).
enum class ContentKey { Text, Code };

struct SourcesRecord {
    std::string fingerprint;
    std::vector<std::string> files;  // as embedded: relative to --base-dir where possible
};

// The record of a run that read `filesRead` (paths as read).
SourcesRecord recordSources(const Options& options, const std::vector<std::string>& filesRead,
                            const SourceReader& reader, ContentKey key = ContentKey::Text);

// The data file's closing comment block holding `record`.
std::string sourcesBlock(const SourcesRecord& record);

// The files (paths to read them by) when `dataText` records sources whose fingerprint
// is still the same; nullopt when anything differs or there is no record.
std::optional<std::vector<std::string>> unchangedSources(const Options& options, const std::string& dataText,
                                                         const SourceReader& reader, ContentKey key = ContentKey::Text);

}  // namespace prism::shaderc
