// The public face of the build step's stages (prism/shaderc/build_step.hpp): each call
// hands its arguments to the stage of its own file and formats the diagnostics once.
#include "prism/shaderc/build_step.hpp"

#include <cctype>
#include <mutex>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "include_resolver.hpp"
#include "module_naming.hpp"
#include "source_reader.hpp"
#include "validator.hpp"

namespace prism::shaderc {

struct Files::Impl {
    std::unique_ptr<SourceReader> reader;
};

struct FlatStage::Record {
    ResolvedStage stage;
};

namespace {

std::vector<Message> messagesOf(const std::vector<Diagnostic>& diagnostics) {
    std::vector<Message> out;
    for (const auto& d : diagnostics)
        out.push_back({d.severity == Severity::Error, formatDiagnostic(d, ErrorFormat::Gcc)});
    return out;
}

ResolveOptions optionsOf(const ResolveSettings& s) {
    return {s.includeDirs, s.defines, s.defaultVersion, s.baseDir};
}

int versionNumberOf(const std::string& directive) {
    std::size_t p = directive.find_first_of("0123456789");
    int v = 0;
    while (p < directive.size() && std::isdigit(static_cast<unsigned char>(directive[p])))
        v = v * 10 + (directive[p++] - '0');
    return v == 0 ? 110 : v;
}

// The validator's stage: the resolver's own record, or one rebuilt from a composed text.
ResolvedStage internalOf(const FlatStage& r) {
    if (r.record) return r.record->stage;
    ResolvedStage out;
    out.text = r.text;
    out.versionDirective = r.text.starts_with("#version") ? r.text.substr(0, r.text.find('\n')) : "";
    out.versionNumber = versionNumberOf(out.versionDirective);
    for (std::uint32_t n = 0; n < r.files.size(); ++n) out.files.push_back({n, r.files[n], r.files[n], {}});
    return out;
}

Contract internalOf(const BindingContract& c) {
    Contract out;
    out.files = c.files;
    out.builtIn = c.builtIn;
    for (const auto& a : c.attributes)
        out.attributes.push_back({a.name, a.type, a.location, {}});  // run time: no JSON entry to name
    for (const auto& u : c.uniforms) out.uniforms.push_back({u.name, u.type, u.array});
    return out;
}

}  // namespace

Files::Files(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Files::Files(Files&&) noexcept = default;
Files& Files::operator=(Files&&) noexcept = default;
Files::~Files() = default;

Files Files::disk() {
    return Files(std::make_unique<Impl>(Impl{std::make_unique<DiskReader>()}));
}

Files Files::memory(std::span<const std::pair<std::string, std::string>> files) {
    auto reader = std::make_unique<MemoryReader>();
    for (const auto& [path, text] : files) reader->add(path, text);
    return Files(std::make_unique<Impl>(Impl{std::move(reader)}));
}

bool hasError(std::span<const Message> messages) {
    for (const auto& m : messages)
        if (m.error) return true;
    return false;
}

Message errorAt(const std::string& file, int line, int column, const std::string& message) {
    return {true, formatDiagnostic(makeError(file, line, column, message), ErrorFormat::Gcc)};
}

ContractLoad loadContract(std::span<const std::string> paths, const Files& files) {
    const auto loaded = loadContracts({paths.begin(), paths.end()}, *files.impl().reader);
    ContractLoad out;
    out.messages = messagesOf(loaded.diagnostics);
    out.ok = !loaded.ioError && !hasError(out.messages);
    out.contract.files = loaded.contract.files;
    out.contract.builtIn = loaded.contract.builtIn;
    for (const auto& a : loaded.contract.attributes)
        out.contract.attributes.push_back({a.name, a.type, glTypeOf(a.type), a.location, 0});
    for (const auto& u : loaded.contract.uniforms)
        out.contract.uniforms.push_back({u.name, u.type, glTypeOf(u.type), 0, u.array});
    return out;
}

StageResolution resolveStage(const std::string& path, const ResolveSettings& settings, const Files& files) {
    auto r = shaderc::resolveStage(path, optionsOf(settings), *files.impl().reader);
    StageResolution out;
    out.ok = r.ok;
    out.messages = messagesOf(r.diagnostics);
    out.resolved.text = r.stage.text;
    for (const auto& f : r.stage.files) out.resolved.files.push_back(f.path);
    out.resolved.filesRead = r.stage.filesRead;
    out.resolved.record = std::make_shared<FlatStage::Record>(FlatStage::Record{std::move(r.stage)});
    return out;
}

ModuleScan scanModule(const std::string& path, const ResolveSettings& settings, const Files& files) {
    auto r = shaderc::scanModule(path, optionsOf(settings), *files.impl().reader);
    ModuleScan out;
    out.ok = r.ok;
    out.messages = messagesOf(r.diagnostics);
    out.module = std::move(r.module);
    return out;
}

std::string canonicalPath(const std::string& path, const Files& files) {
    return files.impl().reader->canonical(path).value_or("");
}

std::string moduleId(std::string_view relativePath) {
    return mangleModulePath(relativePath);
}

Validator::Validator() {
    initializeValidator();
}

Validator::~Validator() {
    finalizeValidator();
}

ProgramCheck checkProgram(std::span<const StageToCheck> stages, const BindingContract& contract) {
    std::vector<StageToValidate> internal;
    for (const auto& s : stages) internal.push_back({s.stage, s.path, internalOf(s.resolved)});
    const ValidatedVariant v = validateProgram(internal, internalOf(contract));
    ProgramCheck out;
    out.messages = messagesOf(v.diagnostics);
    out.ok = v.ok && !hasError(out.messages);
    for (const auto& u : v.reflection.uniforms) out.uniforms.push_back({u.name, u.glType, u.arraySize});
    return out;
}

}  // namespace prism::shaderc
