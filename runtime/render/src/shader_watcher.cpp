// Watches a catalogue's source files and swaps rebuilt programs into the cache (see
// prism/render/shader_watcher.hpp); the change notification is in file_events.cpp, the
// rebuild itself in shader_rebuild.cpp.
#include "prism/render/shader_watcher.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "file_events.hpp"
#include "prism/hash/content_hash.hpp"
#include "shader_rebuild.hpp"

namespace prism::render {
namespace fs = std::filesystem;

namespace {

std::string normalised(const fs::path& p) {
    return fs::absolute(p).lexically_normal().string();
}

std::string variantLabel(const std::string& shader, const std::string& variant) {
    return shader + " (" + variant + ")";
}

const catalog::Variant* findVariantByName(const catalog::Shader& shader, const std::string& name) {
    for (const auto& v : shader.variants)
        if (v.name == name) return &v;
    return nullptr;
}

// gl::ShaderBuildError says "prism: cannot compile ... of 'x':" and then the driver's log
// translated to `path:line:col: error: ...` lines: those lines first, the summary as a note.
std::string driverDiagnostic(const std::string& what) {
    const auto newline = what.find('\n');
    if (newline == std::string::npos) return what + "\n";
    std::string log = what.substr(newline + 1);
    if (!log.empty() && log.back() != '\n') log += '\n';
    std::string summary = what.substr(0, newline);
    if (summary.rfind("prism: ", 0) == 0) summary.erase(0, 7);
    return log + "prism: note: the GL driver rejected what glslang accepted: " + summary + "\n";
}

}  // namespace

ShaderWatchOptions ShaderWatchOptions::from(const catalog::SourceTree& sources, const std::string& movedTo) {
    ShaderWatchOptions options;
    options.sourceRoot = movedTo.empty() ? std::string(sources.baseDir) : movedTo;
    options.moduleDirs.assign(sources.moduleDirs.begin(), sources.moduleDirs.end());
    options.contractFiles.assign(sources.contractFiles.begin(), sources.contractFiles.end());
    for (const auto& d : sources.defines) options.defines.emplace_back(d.name, d.value);
    options.builtInContract = options.contractFiles.empty();
    if (movedTo.empty()) return options;
    // A path under the recorded base dir becomes relative to it, which the watcher joins onto sourceRoot.
    const fs::path base = fs::path(std::string(sources.baseDir)).lexically_normal();
    for (auto* paths : {&options.moduleDirs, &options.contractFiles})
        for (auto& path : *paths)
            if (const auto rel = fs::path(path).lexically_normal().lexically_relative(base);
                !rel.empty() && *rel.begin() != "..")
                path = rel.generic_string();
    return options;
}

ShaderWatcher::ShaderWatcher(ProgramCache& cache, ShaderWatchOptions options)
    : cache_(cache), options_(std::move(options)), events_(detail::makeFileEvents(options_.mechanism)) {
    const fs::path root = options_.sourceRoot.empty() ? fs::current_path() : fs::path(options_.sourceRoot);
    options_.sourceRoot = normalised(root);
    if (options_.moduleDirs.empty()) options_.moduleDirs.push_back(normalised(root / "modules"));
    for (auto& dir : options_.moduleDirs) dir = normalised(root / dir);  // relative dirs: under the root
    if (options_.contractFiles.empty() && !options_.builtInContract)
        options_.contractFiles.push_back(normalised(fs::path(options_.moduleDirs.front()) / "contract.json"));
    for (auto& file : options_.contractFiles) file = normalised(root / file);

    rebuilder_ = std::make_unique<detail::ShaderRebuilder>(options_.contractFiles);
    contractErrors_ = rebuilder_->loadContract();
    for (const auto& file : options_.contractFiles) watch(file);
    for (const auto& shader : cache_.catalog().shaders) {
        auto& deps = dependencies_[std::string(shader.name)];
        for (const auto& variant : shader.variants)
            for (const auto& stage : variant.stages)
                for (const auto& file : stage.files) deps.insert(locate(file));
        for (const auto& file : deps) watch(file);
    }
    lastCheck_ = std::chrono::steady_clock::now();
}

ShaderWatcher::~ShaderWatcher() = default;

WatchMechanism ShaderWatcher::mechanism() const {
    return events_->mechanism();
}

std::string ShaderWatcher::locate(const catalog::SourceFile& file) const {
    if (file.searchDir == 0) return normalised(fs::path(options_.sourceRoot) / std::string(file.path));
    if (file.searchDir > options_.moduleDirs.size())
        throw std::invalid_argument("prism: hot reload: the catalogue read " + std::string(file.path) +
                                    " from -I directory " + std::to_string(file.searchDir) + ", but the options give " +
                                    std::to_string(options_.moduleDirs.size()) +
                                    " moduleDirs; give the build step's -I directories in order "
                                    "(ShaderWatchOptions::from(<ns>::kSourceTree) does)");
    return normalised(fs::path(options_.moduleDirs[file.searchDir - 1]) / std::string(file.path));
}

void ShaderWatcher::watch(const std::string& path) {
    if (files_.count(path)) return;
    events_->add(path);  // first: an edit from here on is reported
    FileState state;
    refresh(path, state);
    files_.emplace(path, state);
}

bool ShaderWatcher::refresh(const std::string& path, FileState& state) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::is_regular_file(status)) {
        const bool changed = state.exists;
        state = FileState{};
        return changed;
    }
    const auto size = fs::file_size(path, ec);
    const auto mtime = fs::last_write_time(path, ec).time_since_epoch().count();
    if (state.exists && !state.racy && size == state.size && mtime == state.mtime) return false;
    const auto readAt = fs::file_time_type::clock::now();
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const auto hash = hash::hash64(text.str());
    const bool changed = !state.exists || hash != state.hash;
    const auto racyWindow = std::chrono::duration_cast<fs::file_time_type::duration>(std::chrono::seconds(2));
    const bool racy = mtime >= (readAt - racyWindow).time_since_epoch().count();
    state = {true, static_cast<std::int64_t>(mtime), size, hash, racy};
    return changed;
}

WatchPollResult ShaderWatcher::poll() {
    const bool polling = events_->mechanism() == WatchMechanism::Polling;
    if (polling && std::chrono::steady_clock::now() - lastCheck_ < options_.pollInterval) return {};
    return pollNow();
}

WatchPollResult ShaderWatcher::pollNow() {
    WatchPollResult result;
    result.checked = true;
    lastCheck_ = std::chrono::steady_clock::now();
    const auto touched = events_->touched();  // nullopt: look at every file
    for (auto& [path, state] : files_)
        if ((!touched || touched->count(path)) && refresh(path, state)) result.changedFiles.push_back(path);

    std::set<std::string> seenDiagnostics;
    bool contractChanged = false;
    for (const auto& changed : result.changedFiles)
        for (const auto& file : options_.contractFiles) contractChanged = contractChanged || changed == file;
    if (contractChanged) {
        contractErrors_ = rebuilder_->loadContract();
        for (const auto& d : contractErrors_)
            if (seenDiagnostics.insert(d).second) result.diagnostics.push_back(d);
    }
    for (const auto& [shader, deps] : dependencies_) {
        bool affected = contractChanged;
        for (const auto& changed : result.changedFiles) affected = affected || deps.count(changed) > 0;
        if (!affected) continue;
        editedShaders_.insert(shader);
        for (auto it = current_.begin(); it != current_.end();) it = it->first == shader ? current_.erase(it) : ++it;
    }
    if (!contractErrors_.empty()) return result;  // nothing can be checked against a broken contract

    for (const auto& shader : editedShaders_)
        for (const auto& variant : cache_.builtVariants(shader))
            if (!current_.count({shader, variant})) rebuild(shader, variant, result, seenDiagnostics);
    return result;
}

void ShaderWatcher::rebuild(const std::string& shader, const std::string& variantName, WatchPollResult& result,
                            std::set<std::string>& seenDiagnostics) {
    const VariantKey key{shader, variantName};
    current_.insert(key);  // rebuilt again only after the next edit
    const auto* catalogShader = catalog::findShader(cache_.catalog(), shader);
    const auto* variant = catalogShader ? findVariantByName(*catalogShader, variantName) : nullptr;
    if (!variant) return;

    detail::RebuildRequest request;
    request.label = variantLabel(shader, variantName);
    request.includeDirs = options_.moduleDirs;
    request.versionDirective = std::string(cache_.catalog().versionDirective);
    request.defines = options_.defines;
    for (const auto& d : variant->defines) request.defines.emplace_back(d.name, d.value);
    for (const auto& stage : variant->stages) {
        const auto* stageFile = catalog::findSourceFile(stage, 0);
        if (!stageFile) return;
        request.stages.push_back({stage.stage, locate(*stageFile)});
    }

    auto outcome = rebuilder_->rebuild(request);
    auto& deps = dependencies_[shader];
    for (const auto& file : outcome.filesRead) {  // a newly included module is watched from now on
        const auto path = normalised(file);
        deps.insert(path);
        watch(path);
    }
    std::vector<std::string> errors = std::move(outcome.diagnostics);
    if (outcome.sources) {
        outcome.sources->variant = variant;  // the rebuilt program still knows its shader
        try {
            cache_.reload(shader, variantName, gl::Program(std::move(*outcome.sources)));
            result.reloaded.push_back(request.label);
        } catch (const gl::ShaderBuildError& e) {  // the driver disagreed with glslang
            errors.push_back(driverDiagnostic(e.what()));
        }
    }
    if (errors.empty()) {
        errors_.erase(key);
        return;
    }
    for (const auto& d : errors)
        if (seenDiagnostics.insert(d).second) result.diagnostics.push_back(d);
    errors_[key] = std::move(errors);
}

std::vector<std::string> ShaderWatcher::errors() const {
    std::vector<std::string> all;
    std::set<std::string> seen;
    for (const auto& d : contractErrors_)
        if (seen.insert(d).second) all.push_back(d);
    for (const auto& [key, list] : errors_)
        for (const auto& d : list)
            if (seen.insert(d).second) all.push_back(d);
    return all;
}

std::vector<std::string> ShaderWatcher::watchedFiles() const {
    std::vector<std::string> paths;
    for (const auto& [path, state] : files_) paths.push_back(path);
    return paths;
}

}  // namespace prism::render
