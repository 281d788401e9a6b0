// The outputs of a run (see outputs.hpp).
#include "outputs.hpp"

#include <filesystem>

#include "depfile.hpp"
#include "output_file.hpp"
#include "output_generator.hpp"
#include "tool_identity.hpp"

namespace prism::shaderc {
namespace {

// Writes `files` in order; on failure removes those of them that did not exist before.
std::string writeGeneratedFiles(const std::vector<GeneratedFile>& files) {
    std::string error;
    std::vector<std::string> created;
    for (const GeneratedFile& f : files) {
        const bool existed = std::filesystem::exists(f.path);
        if (writeIfChanged(f.path, f.bytes, error) == WriteOutcome::Failed) {
            std::error_code ec;
            for (const std::string& path : created) std::filesystem::remove(path, ec);  // nothing new on failure
            return error;
        }
        if (!existed) created.push_back(f.path);
    }
    return {};
}

}  // namespace

std::string writeOutputs(const Options& o, const ResolvedCatalog& rc) {
    for (const auto& generator : outputGenerators()) {
        if (generator->pathsNamed(o).empty()) continue;
        if (std::string error = writeGeneratedFiles(generator->generate(o, rc)); !error.empty()) return error;
    }
    return {};
}

std::string writeBuildSystemFiles(const Options& o, const std::vector<std::string>& filesRead) {
    std::string error;
    const std::string target = !o.stamp.empty() ? o.stamp : o.output;
    if (!o.depfile.empty() && !target.empty() &&
        writeIfChanged(o.depfile, makeDepfile(target, filesRead), error) == WriteOutcome::Failed)
        return error;
    if (!o.stamp.empty() && !touchFile(o.stamp, stampText(), error)) return error;
    return {};
}

}  // namespace prism::shaderc
