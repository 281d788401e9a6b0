// The outputs of a run (see outputs.hpp).
#include "outputs.hpp"

#include <filesystem>

#include "data_writer.hpp"
#include "depfile.hpp"
#include "glsl_emitter.hpp"
#include "header_writer.hpp"
#include "output_file.hpp"
#include "reflection_writer.hpp"
#include "tool_identity.hpp"
#include "shader_targets.hpp"
#include "web_writer.hpp"

namespace prism::shaderc {

std::string writeOutputs(const Options& o, const ResolvedCatalog& rc) {
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
            return error;
        }
    }
    if (!o.emitSpirvDir.empty() && !emitSpirv(o.emitSpirvDir, rc.data, error)) return error;
    if (!o.emitWeb.empty() &&
        writeIfChanged(o.emitWeb, writeWebCatalogue(rc.data, std::filesystem::path(o.emitWeb).stem().string()),
                       error) == WriteOutcome::Failed)
        return error;
    if (!o.emitReflection.empty() &&
        writeIfChanged(o.emitReflection, writeReflectionJson(rc.data), error) == WriteOutcome::Failed)
        return error;
    if (o.emitGlslDir.empty()) return {};
    std::vector<std::vector<Target>> targets(rc.data.shaders.size());
    for (std::size_t s = 0; s < targets.size(); ++s)
        for (const Target t : o.targets)
            if (producedFor(o, rc, s, t)) targets[s].push_back(t);
    if (!emitGlsl(o.emitGlslDir, rc.data, o.targets, targets, error)) return error;
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
