// The no-op check on recorded sources (see source_fingerprint.hpp).
#include "source_fingerprint.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "code_signature.hpp"
#include "generated_format.hpp"
#include "prism/hash/content_hash.hpp"
#include "program_declarations.hpp"
#include "shader_inputs.hpp"
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

std::string fingerprintOf(const Options& o, const std::vector<std::string>& embedded, const SourceReader& reader,
                          ContentKey key) {
    hash::ContentHash h;
    h.add(PRISM_VERSION);
    h.add(format::kLayoutVersion);
    // A code record lives in the cache directory, not in an output, so it can name the build
    // that checked (tool_identity.hpp); a text record is in the data file, which must not.
    if (key == ContentKey::Code) h.add("code signatures").add(toolIdentity());  // never equal to a text record
    // Only the options that change the generated files, with paths as embedded (never
    // --depfile, --stamp, --emit-glsl, -j or the error format).
    const auto shown = [&](const std::string& dir) { return recordedName(dir, o); };
    h.add("ns " + o.nameSpace);
    h.add("glsl " + std::to_string(o.glslVersion) + " " + o.glslProfile);
    if (o.rules.spirvEnv) h.add("client vulkan " + std::string(spirvEnvName(*o.rules.spirvEnv)));
    h.add("out " + fs::path(o.output).filename().string());
    for (const auto& [name, value] : o.defines) h.add("-D " + name + "=" + value);
    for (const auto& filter : o.variantFilters) h.add("--variant " + filter);
    if (o.targets != std::vector<Target>{Target::Gl}) h.add("--target " + targetListText(o.targets));
    for (const auto& contract : o.contracts) h.add("--contract " + shown(contract));
    for (const auto& dir : o.includeDirs) h.add("-I " + shown(dir));
    for (const auto& input : o.inputs) h.add("in " + shown(input));
    for (const auto& declaration : o.programs) h.add("--program " + declarationWithPaths(declaration, shown));
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

}  // namespace

SourcesRecord recordSources(const Options& o, const std::vector<std::string>& filesRead, const SourceReader& reader,
                            ContentKey key) {
    const std::set<std::string> named(filesRead.begin(), filesRead.end());  // each stage lists its files
    std::set<std::string> unique;
    for (const auto& f : named) unique.insert(recordedName(f, o));
    SourcesRecord record;
    record.files.assign(unique.begin(), unique.end());
    record.fingerprint = fingerprintOf(o, record.files, reader, key);
    return record;
}

std::string sourcesBlock(const SourcesRecord& record) {
    std::string block = std::string(kSourcesRecordStart) + record.fingerprint + "\n";
    for (const auto& f : record.files) block += std::string(kSourcesRecordFile) + f + "\n";
    return block;
}

std::optional<std::vector<std::string>> unchangedSources(const Options& o, const std::string& header,
                                                         const SourceReader& reader, ContentKey key) {
    const auto start = header.rfind(kSourcesRecordStart);
    if (start == std::string::npos) return std::nullopt;
    std::istringstream in(header.substr(start + kSourcesRecordStart.size()));
    SourcesRecord recorded;
    std::getline(in, recorded.fingerprint);
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with(kSourcesRecordFile)) return std::nullopt;
        recorded.files.push_back(line.substr(kSourcesRecordFile.size()));
    }
    if (recorded.files.empty() || fingerprintOf(o, recorded.files, reader, key) != recorded.fingerprint)
        return std::nullopt;
    std::vector<std::string> paths;
    for (const auto& f : recorded.files) paths.push_back(recordedToPath(f, o));
    return paths;
}

}  // namespace prism::shaderc
