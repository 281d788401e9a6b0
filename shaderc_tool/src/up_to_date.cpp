// The one record of "nothing changed" (see up_to_date.hpp).
#include "up_to_date.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "data_file_records.hpp"
#include "output_file.hpp"
#include "output_options.hpp"
#include "prism/hash/content_hash.hpp"
#include "shown_path.hpp"
#include "source_fingerprint.hpp"

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kRecordStart = "prism-shaderc run record 1\n";
constexpr std::string_view kKeyTag = "key ", kReadTag = "read ", kWroteTag = "wrote ";

// Names the record in a shared cache directory: the options that change outputs, with the
// output paths as given, so catalogues sharing the directory keep records of their own.
// A --check that writes no file depends only on the code signatures of what it read.
ContentKey contentKey(const Options& o) {
    const bool writesFiles = !o.output.empty() || !o.emitGlslDir.empty() || !o.emitSpirvDir.empty() ||
                             !o.emitWeb.empty() || !o.emitReflection.empty();
    return o.checkOnly && !writesFiles ? ContentKey::Code : ContentKey::Text;
}

// Every file the run writes, but the depfile and stamp (rewritten by every run, the no-op too).
std::vector<std::string> filesWritten(const Options& o) {
    std::vector<std::string> files;
    if (!o.checkOnly && !o.output.empty()) files = {o.output, dataPathFor(o.output)};
    for (const auto* file : {&o.emitWeb, &o.emitReflection})
        if (!file->empty()) files.push_back(*file);
    for (const auto* dir : {&o.emitGlslDir, &o.emitSpirvDir}) {
        std::vector<std::string> emitted;
        std::error_code ec;
        for (auto it = fs::directory_iterator(*dir, ec); !dir->empty() && !ec && it != fs::directory_iterator();
             it.increment(ec))
            if (it->is_regular_file(ec)) emitted.push_back(it->path().string());
        std::sort(emitted.begin(), emitted.end());
        files.insert(files.end(), emitted.begin(), emitted.end());
    }
    return files;
}

// "<size> <modification time> <path>": an output deleted or rewritten by hand no longer matches.
std::string fileState(const std::string& path) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) return "missing " + path;
    const auto time = fs::last_write_time(path, ec).time_since_epoch().count();
    return std::to_string(size) + " " + std::to_string(time) + " " + path;
}

struct RecordedRun {
    std::string key;
    std::vector<std::string> filesRead;   // as embedded
    std::vector<std::string> filesWrote;  // as fileState() printed them
};

std::optional<RecordedRun> readRecord(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    if (!in || !std::getline(in, line) || line + "\n" != kRecordStart) return std::nullopt;
    RecordedRun run;
    while (std::getline(in, line)) {
        if (line.starts_with(kKeyTag))
            run.key = line.substr(kKeyTag.size());
        else if (line.starts_with(kReadTag))
            run.filesRead.push_back(line.substr(kReadTag.size()));
        else if (line.starts_with(kWroteTag))
            run.filesWrote.push_back(line.substr(kWroteTag.size()));
        else
            return std::nullopt;
    }
    if (run.key.empty() || run.filesRead.empty()) return std::nullopt;
    return run;
}

void removeStaleOutputTemps(const Options& o) {  // nothing to write, but a killed run may have left temp files
    if (o.output.empty()) return;
    removeStaleTemps(o.output);
    removeStaleTemps(dataPathFor(o.output));
}

}  // namespace

std::string runRecordPath(const Options& o) {
    hash::ContentHash h;
    h.add("run record").add(o.baseDir).add(o.output);
    for (const auto& line : outputOptionLines(o)) h.add(line);
    if (const std::string dir = validationCacheDir(o); !dir.empty())
        return (fs::path(dir) / (h.hex64() + ".record")).string();
    return o.output.empty() ? std::string() : o.output + ".record";
}

std::optional<Unchanged> unchangedSinceLastRun(const Options& o, const SourceReader& reader) {
    const std::string path = runRecordPath(o);
    if (path.empty() || o.revalidate) return std::nullopt;
    const auto recorded = readRecord(path);
    if (!recorded) return std::nullopt;
    for (const auto& state : recorded->filesWrote) {
        const auto pathStart = state.find(' ', state.find(' ') + 1);
        if (pathStart == std::string::npos || fileState(state.substr(pathStart + 1)) != state) return std::nullopt;
    }
    if (sourcesFingerprint(o, recorded->filesRead, reader, contentKey(o), RecordScope::Run) != recorded->key)
        return std::nullopt;
    removeStaleOutputTemps(o);
    if (o.printStats && o.checkOnly)
        std::cerr << "prism-shaderc: no code changed since the last clean check; nothing validated\n";
    Unchanged unchanged;
    for (const auto& f : recorded->filesRead) unchanged.filesRead.push_back(recordedToPath(f, o));
    return unchanged;
}

void rememberRun(const Options& o, const std::vector<std::string>& filesRead, const DiagnosticSink& sink,
                 const SourceReader& reader) {
    const std::string path = runRecordPath(o);
    if (path.empty()) return;
    if (o.checkOnly && !sink.diagnostics().empty()) return forgetRun(o);  // its diagnostics must print again
    const auto files = embeddedNames(o, filesRead);
    std::string record(kRecordStart);
    record += std::string(kKeyTag) + sourcesFingerprint(o, files, reader, contentKey(o), RecordScope::Run) + "\n";
    for (const auto& f : files) record += std::string(kReadTag) + f + "\n";
    for (const auto& f : filesWritten(o)) record += std::string(kWroteTag) + fileState(f) + "\n";
    std::error_code ec;
    if (const auto parent = fs::path(path).parent_path(); !parent.empty()) fs::create_directories(parent, ec);
    std::string error;
    if (writeIfChanged(path, record, error) == WriteOutcome::Failed)
        std::cerr << "prism-shaderc: warning: the run record was not written (the next run is a full one): " << error
                  << "\n";
}

void forgetRun(const Options& o) {
    std::error_code ec;
    if (const std::string path = runRecordPath(o); !path.empty()) fs::remove(path, ec);
}

}  // namespace prism::shaderc
