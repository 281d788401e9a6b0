// prism-shaderc: the build-time GLSL toolchain. main() only sequences the stages:
//   args -> no-op check on the recorded sources (--check: on the last clean check's code
//   signatures) -> shader inputs -> contract
//   -> include resolution + variants -> validation
//   (glslang, interface and contract checks, reflection) -> header + data file, GLSL, depfile.
// Exit status: 0 success, 1 shader errors, 2 usage or I/O errors.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "clean_check.hpp"
#include "contract.hpp"
#include "data_writer.hpp"
#include "depfile.hpp"
#include "diagnostics.hpp"
#include "generated_format.hpp"
#include "glsl_emitter.hpp"
#include "header_writer.hpp"
#include "output_file.hpp"
#include "shader_inputs.hpp"
#include "source_fingerprint.hpp"
#include "source_reader.hpp"
#include "validation_scheduler.hpp"
#include "validation_settings.hpp"

using namespace prism::shaderc;

namespace {

constexpr int kExitOk = 0, kExitShaderErrors = 1, kExitUsageOrIo = 2;

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
    return tail.find("\n" + std::string(format::kSourcesRecordStart)) != std::string::npos ? tail
                                                                                          : readWholeFile(path);
}

// The data file records the fingerprint and is written after the header, so a run killed
// between the two leaves a stale record that the next run does not trust.
// The header must be the one the data file records (not deleted, edited or left stale).
bool outputsAreCurrent(const Options& o, const std::string& fingerprint) {
    if (o.checkOnly || o.output.empty() || !o.emitGlslDir.empty()) return false;
    const auto data = readWholeFile(dataPathFor(o.output));
    return headerMatchesData(readWholeFile(o.output), data) && recordedFingerprint(data) == fingerprint;
}

void removeStaleOutputTemps(const Options& o) {  // nothing to write, but a killed run may have left temp files
    removeStaleTemps(o.output);
    removeStaleTemps(dataPathFor(o.output));
}

int writeOutputs(const Options& o, const ResolvedCatalog& rc) {
    std::string error;
    const auto name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
    if (!o.output.empty()) {
        const std::string data = dataPathFor(o.output);
        const std::string header = writeHeader(rc.data, name(data));
        const bool headerExisted = std::filesystem::exists(o.output);
        if (writeIfChanged(o.output, header, error) == WriteOutcome::Failed ||
            writeIfChanged(data, writeData(rc.data, name(o.output), header), error) == WriteOutcome::Failed) {
            std::error_code ec;
            if (!headerExisted) std::filesystem::remove(o.output, ec);  // nothing written on failure
            std::cerr << "prism-shaderc: error: " << error << "\n";
            return kExitUsageOrIo;
        }
    }
    if (!o.emitGlslDir.empty() && !emitGlsl(o.emitGlslDir, rc.data, error)) {
        std::cerr << "prism-shaderc: error: " << error << "\n";
        return kExitUsageOrIo;
    }
    return kExitOk;
}

int writeBuildSystemFiles(const Options& o, const std::vector<std::string>& filesRead) {
    std::string error;
    const std::string target = !o.stamp.empty() ? o.stamp : o.output;
    if (!o.depfile.empty() && !target.empty() &&
        writeIfChanged(o.depfile, makeDepfile(target, filesRead), error) == WriteOutcome::Failed) {
        std::cerr << "prism-shaderc: error: " << error << "\n";
        return kExitUsageOrIo;
    }
    if (!o.stamp.empty() && !touchFile(o.stamp, error)) {
        std::cerr << "prism-shaderc: error: " << error << "\n";
        return kExitUsageOrIo;
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    auto args = parseArgs(argc, argv);
    if (!args.options) return args.exitCode;
    const Options& o = *args.options;
    DiagnosticSink sink;
    DiskReader disk;

    const bool writesHeaderOnly = !o.checkOnly && !o.output.empty() && o.emitGlslDir.empty();
    if (writesHeaderOnly && dataPathFor(o.output) == o.output) {
        std::cerr << "prism-shaderc: error: -o " << o.output
                  << ": the data file would overwrite the header; name the header .hpp or .h\n";
        return kExitUsageOrIo;
    }
    if (writesHeaderOnly)
        if (const auto record = readRecord(dataPathFor(o.output)); headerMatchesData(readWholeFile(o.output), record))
            if (auto files = unchangedSources(o, record, disk)) {
                removeStaleOutputTemps(o);
                return writeBuildSystemFiles(o, *files);
            }

    if (auto files = unchangedSinceCleanCheck(o, disk)) {
        if (o.printStats) std::cerr << "prism-shaderc: no code changed since the last clean check; nothing validated\n";
        return writeBuildSystemFiles(o, *files);
    }

    auto inputs = collectShaderInputs(o.inputs);
    sink.reportAll(inputs.diagnostics);
    auto contract = loadContracts(o.contracts, disk);
    sink.reportAll(contract.diagnostics);

    if (inputs.ioError || contract.ioError) {
        sink.print(std::cerr, o.errorFormat);
        return kExitUsageOrIo;
    }

    auto catalog = resolveCatalog(o, inputs.shaders, contract.contract, disk, sink);
    if (!o.checkOnly && !o.output.empty()) {  // what the data file records
        catalog.data.sourcesBlock = sourcesBlock(recordSources(o, catalog.filesRead, disk));
        catalog.data.fingerprint = fingerprint(catalog);
    }
    if (sink.errorCount() == 0 && outputsAreCurrent(o, catalog.data.fingerprint)) {
        removeStaleOutputTemps(o);
        sink.print(std::cerr, o.errorFormat);
        return writeBuildSystemFiles(o, catalog.filesRead);
    }
    if (sink.errorCount() == 0) {
        ValidationCache cache(validationCacheDir(o), catalogueCacheKey(o));
        const auto stats = validateCatalogScheduled(catalog, contract.contract, o.jobs, cache, sink);
        if (o.printStats) printResolutionStats(std::cerr, catalog);
        if (o.printStats) printValidationStats(std::cerr, stats);
    }

    sink.print(std::cerr, o.errorFormat);
    if (sink.diagnostics().empty())
        recordCleanCheck(o, catalog.filesRead, disk);
    else
        forgetCleanCheck(o);
    if (sink.errorCount() > 0) {
        std::cerr << "prism-shaderc: " << sink.errorCount() << " error(s); nothing written\n";
        return kExitShaderErrors;
    }
    if (int rc = writeOutputs(o, catalog); rc != kExitOk) return rc;
    return writeBuildSystemFiles(o, catalog.filesRead);
}
