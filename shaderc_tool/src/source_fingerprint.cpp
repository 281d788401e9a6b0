// The no-op check on recorded sources (see source_fingerprint.hpp).
#include "source_fingerprint.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "code_signature.hpp"
#include "output_options.hpp"
#include "generated_format.hpp"
#include "prism/hash/content_hash.hpp"
#include "stage_files.hpp"
#include "shown_path.hpp"
#include "tool_identity.hpp"

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;

using format::kSourcesRecordFile;
using format::kSourcesRecordStart;

// The sorted names of `dir`'s regular files whose extension passes `keep`.
std::vector<std::string> listing(const std::string& dir, bool (*keep)(const fs::path&)) {
    std::vector<std::string> names;
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec) && keep(it->path())) names.push_back(it->path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

bool isModule(const fs::path& p) {
    return p.extension() == kModuleExtension;
}
bool isStage(const fs::path& p) {
    return stageOfPath(p).has_value();
}

}  // namespace

// `lines`: the options that change the outputs (output_options.hpp), then each file read and
// the listings of the searched folders.
std::string sourcesFingerprint(const Options& o, const std::vector<std::string>& embedded, const SourceReader& reader,
                               ContentKey key, RecordScope scope) {
    hash::ContentHash h;
    h.add(PRISM_VERSION);
    h.add(format::kLayoutVersion);
    // The run record names the build that wrote it (tool_identity.hpp); the data file's
    // record is in an output, which must not (reproducible, relocatable bytes).
    if (scope == RecordScope::Run) h.add("run record").add(toolIdentity());
    if (key == ContentKey::Code) h.add("code signatures");  // never equal to a text record
    const auto shown = [&](const std::string& dir) { return recordedName(dir, o); };
    for (const auto& line :
         scope == RecordScope::DataFile ? outputOptionLines(o, kDataFileRecord) : outputOptionLines(o))
        h.add(line);
    for (const auto& file : embedded) {
        h.add(file);
        const auto text = reader.read(recordedToPath(file, o));
        if (!text)
            h.add(std::string("\0missing", 8));
        else if (key == ContentKey::Code && hasCodeSignature(file))
            h.add(codeSignature(*text));
        else
            h.add(*text);
    }
    // Folders as embedded (relative to --base-dir), so that the same tree checked out at
    // another absolute path gives the same fingerprint and byte-identical outputs.
    for (const auto& dir : o.includeDirs)
        for (const auto& name : listing(dir, isModule)) h.add("-I " + shown(dir) + "/" + name);
    for (const auto& input : o.inputs)
        for (const auto& name : listing(input, isStage)) h.add("in " + shown(input) + "/" + name);
    return h.hex64();
}

std::vector<std::string> embeddedNames(const Options& o, const std::vector<std::string>& filesRead) {
    const std::set<std::string> named(filesRead.begin(), filesRead.end());  // each stage lists its files
    std::set<std::string> unique;
    for (const auto& f : named) unique.insert(recordedName(f, o));
    return {unique.begin(), unique.end()};
}

SourcesRecord recordSources(const Options& o, const std::vector<std::string>& filesRead, const SourceReader& reader) {
    SourcesRecord record;
    record.files = embeddedNames(o, filesRead);
    record.fingerprint = sourcesFingerprint(o, record.files, reader, ContentKey::Text, RecordScope::DataFile);
    return record;
}

std::string sourcesBlock(const SourcesRecord& record) {
    std::string block = std::string(kSourcesRecordStart) + record.fingerprint + "\n";
    for (const auto& f : record.files) block += std::string(kSourcesRecordFile) + f + "\n";
    return block;
}

}  // namespace prism::shaderc
