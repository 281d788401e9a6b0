// prism-shaderc's command line (prism/shaderc/tool.hpp). runTool() only sequences the stages, each a
// function of its own file that returns its result with its diagnostics, which runTool()
// gathers and prints once, at the end:
//   1 args.hpp                 the command line
//   2 up_to_date.hpp           nothing changed? (the one record, before any input is read)
//   3 shader_inputs.hpp        the stage files, and the binding contract (contract.hpp)
//   4 catalog_builder.hpp      include resolution and variants
//   5 validation_scheduler.hpp glslang, interface and contract checks, reflection; then
//     shader_targets.hpp, es300_target.hpp, spirv_target.hpp: what each target refuses, the
//     es300 checks, the SPIR-V
//   6 outputs.hpp              every output generator (output_generator.hpp), depfile and stamp
// Exit status: 0 success, 1 shader errors, 2 usage or I/O errors.
#include "prism/shaderc/tool.hpp"

#include <iostream>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "contract.hpp"
#include "diagnostics.hpp"
#include "es300_target.hpp"
#include "outputs.hpp"
#include "shader_inputs.hpp"
#include "shader_targets.hpp"
#include "source_reader.hpp"
#include "spirv_target.hpp"
#include "up_to_date.hpp"
#include "validation_scheduler.hpp"

namespace prism::shaderc {
namespace {

constexpr int kExitOk = 0, kExitShaderErrors = 1, kExitUsageOrIo = 2;

int exitStatus(const std::string& ioError) {
    if (ioError.empty()) return kExitOk;
    std::cerr << "prism-shaderc: error: " << ioError << "\n";
    return kExitUsageOrIo;
}

}  // namespace

int runTool(int argc, char** argv) {
    const auto args = parseArgs(argc, argv);
    if (!args.options) return args.exitCode;
    const Options& o = *args.options;
    DiskReader disk;
    if (const auto unchanged = unchangedSinceLastRun(o, disk))
        return exitStatus(writeBuildSystemFiles(o, unchanged->filesRead));

    DiagnosticSink sink;
    const auto inputs = collectShaderInputs(o.inputs, o.programs, o.rules);
    sink.reportAll(inputs.diagnostics);
    const auto contract = loadContracts(o.contracts, disk);
    sink.reportAll(contract.diagnostics);
    if (inputs.ioError || contract.ioError) {
        sink.print(std::cerr, o.errorFormat);
        return kExitUsageOrIo;
    }

    auto catalog = resolveCatalog(o, inputs.shaders, contract.contract, disk);
    sink.reportAll(catalog.diagnostics);
    fillDataFileRecord(o, catalog, disk);

    if (sink.errorCount() == 0) sink.reportAll(checkShaderTargets(o, catalog));
    if (sink.errorCount() == 0) sink.reportAll(validateCatalog(o, catalog, contract.contract).diagnostics);
    if (sink.errorCount() == 0) sink.reportAll(validateEs300(o, catalog, contract.contract));
    if (sink.errorCount() == 0) sink.reportAll(buildSpirvTarget(o, catalog, contract.contract));
    sink.print(std::cerr, o.errorFormat);
    if (sink.errorCount() > 0) {
        forgetRun(o);
        std::cerr << "prism-shaderc: " << sink.errorCount() << " error(s); nothing written\n";
        return kExitShaderErrors;
    }
    if (const int status = exitStatus(writeOutputs(o, catalog)); status != kExitOk) {
        forgetRun(o);
        return status;
    }
    rememberRun(o, catalog.filesRead, sink, disk);
    return exitStatus(writeBuildSystemFiles(o, catalog.filesRead));
}

}  // namespace prism::shaderc
