// prism-shaderc: the build-time GLSL toolchain. main() only sequences the stages:
//   args -> no-op check on the recorded sources -> shader inputs -> contract
//   -> include resolution + variants -> validation
//   (glslang, interface and contract checks, reflection) -> header, GLSL, depfile.
// Exit status: 0 success, 1 shader errors, 2 usage or I/O errors.
#include <fstream>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "contract.hpp"
#include "depfile.hpp"
#include "diagnostics.hpp"
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

bool headerIsCurrent(const Options& o, const std::string& fingerprint) {
    return !o.checkOnly && !o.output.empty() && o.emitGlslDir.empty() &&
           fingerprintOfHeader(readWholeFile(o.output)) == fingerprint;
}

int writeOutputs(const Options& o, const ResolvedCatalog& rc) {
    std::string error;
    if (!o.output.empty() && writeIfChanged(o.output, writeHeader(rc.data), error) == WriteOutcome::Failed) {
        std::cerr << "prism-shaderc: error: " << error << "\n";
        return kExitUsageOrIo;
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
    if (writesHeaderOnly)
        if (auto files = unchangedSources(o, readWholeFile(o.output), disk)) {
            removeStaleTemps(o.output);  // nothing to write, but a killed run may have left a temp file
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
    catalog.data.commandLine = o.commandLine;
    catalog.data.sourcesBlock = sourcesBlock(recordSources(o, catalog.filesRead, disk));
    catalog.data.fingerprint = fingerprint(catalog);
    if (sink.errorCount() == 0 && headerIsCurrent(o, catalog.data.fingerprint)) {
        removeStaleTemps(o.output);  // nothing to write, but a killed run may have left a temp file
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
    if (sink.errorCount() > 0) {
        std::cerr << "prism-shaderc: " << sink.errorCount() << " error(s); nothing written\n";
        return kExitShaderErrors;
    }
    if (int rc = writeOutputs(o, catalog); rc != kExitOk) return rc;
    return writeBuildSystemFiles(o, catalog.filesRead);
}
