// Module libraries read at run time through the build step's library,
// prism/shaderc/build_step.hpp (see prism/gl/module_library.hpp).
#include "prism/gl/module_library.hpp"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>

#include "compose_check.hpp"
#include "prism/catalog/did_you_mean.hpp"
#include "prism/gl/compose.hpp"
#include "prism/shaderc/build_step.hpp"

namespace prism::gl {

struct ModuleLibrary::Storage {
    std::deque<std::string> strings;  // every name, path, description and text the views point into
    std::vector<std::vector<std::string_view>> chunks;
    std::vector<std::vector<std::uint32_t>> dependencies;
    std::vector<catalog::Module> modules;
    std::vector<catalog::Attribute> attributes;
    std::vector<catalog::Uniform> uniforms;
    std::vector<std::string> names;          // module ids, the build step's
    std::vector<std::string> contractFiles;  // named in composition's contract errors
    catalog::Catalog view{};

    std::string_view keep(std::string s) { return strings.emplace_back(std::move(s)); }
};

namespace {

namespace sc = prism::shaderc;

[[noreturn]] void fail(const std::string& what, const std::vector<sc::Message>& messages) {
    throw detail::compositionError("prism module library: " + what, messages);
}

std::string folderOf(const std::string& path) {
    return std::filesystem::path(path).lexically_normal().parent_path().generic_string();
}

// The build step's roots: the given include directories, else each module's own folder.
std::vector<std::string> includeDirsOf(const std::vector<std::string>& moduleFiles,
                                       const std::vector<std::string>& includeDirs) {
    std::vector<std::string> dirs = includeDirs;
    if (dirs.empty())
        for (const auto& f : moduleFiles)
            if (std::find(dirs.begin(), dirs.end(), folderOf(f)) == dirs.end()) dirs.push_back(folderOf(f));
    return dirs;
}

// The build step's module id: the path under the first root holding it, mangled.
std::string idOf(const std::string& path, const std::vector<std::string>& roots) {
    const auto normal = std::filesystem::path(path).lexically_normal();
    for (const auto& root : roots) {
        const auto relative = normal.lexically_relative(std::filesystem::path(root).lexically_normal());
        if (!relative.empty() && *relative.begin() != "..") return sc::moduleId(relative.generic_string());
    }
    return sc::moduleId(normal.filename().generic_string());
}

void addContract(ModuleLibrary::Storage& s, const std::vector<std::string>& contractFiles, const sc::Files& files) {
    const auto loaded = sc::loadContract(contractFiles, files);
    if (!loaded.ok || !loaded.messages.empty()) fail("the contract could not be read", loaded.messages);
    for (const auto& a : loaded.contract.attributes) s.attributes.push_back({s.keep(a.name), a.glType, a.location});
    for (const auto& u : loaded.contract.uniforms)
        s.uniforms.push_back({s.keep(u.name), u.glType, u.array > 0 ? u.array : 1});
    for (const auto& f : loaded.contract.files) s.contractFiles.push_back(f);
}

// A cycle among the modules' includes, reported as the build step reports it: the
// resolver run on the module where it starts (file:line, the chain, the guard hint).
void checkCycles(const std::vector<sc::ModuleText>& modules, const std::vector<std::vector<std::uint32_t>>& deps,
                 const sc::ResolveSettings& settings, const sc::Files& files) {
    std::vector<int> state(modules.size(), 0);  // 0 new, 1 open, 2 done
    std::function<bool(std::uint32_t)> cyclic = [&](std::uint32_t m) {
        if (state[m] != 0) return state[m] == 1;
        state[m] = 1;
        for (std::uint32_t d : deps[m])
            if (cyclic(d)) return true;
        state[m] = 2;
        return false;
    };
    for (std::uint32_t m = 0; m < modules.size(); ++m) {
        if (!cyclic(m)) continue;
        const auto r = sc::resolveStage(modules[m].path, settings, files);
        if (sc::hasError(r.messages)) fail("an include cycle", r.messages);
        std::fill(state.begin(), state.end(), 0);  // guarded: the build step accepts it
    }
}

std::unique_ptr<ModuleLibrary::Storage> build(const std::vector<std::string>& moduleFiles,
                                              const std::vector<std::string>& contractFiles,
                                              const std::vector<std::string>& includeDirs, const sc::Files& files,
                                              std::string versionDirective) {
    auto s = std::make_unique<ModuleLibrary::Storage>();
    addContract(*s, contractFiles, files);
    sc::ResolveSettings settings;
    settings.includeDirs = includeDirsOf(moduleFiles, includeDirs);
    std::map<std::string, std::uint32_t> idByCanonical;
    std::map<std::string, std::string> pathById;
    std::vector<sc::ModuleText> sources;
    for (const auto& f : moduleFiles) {
        auto scan = sc::scanModule(f, settings, files);
        if (!scan.ok) fail("module " + f + " could not be read", scan.messages);
        const std::string id = idOf(f, settings.includeDirs);
        if (auto [it, fresh] = pathById.emplace(id, f); !fresh)
            fail("two modules have one id", {sc::errorAt(f, 0, 0,
                                                         "module id '" + id + "' is also " + it->second +
                                                             "'s; pass their common root as an include "
                                                             "directory so that their ids differ")});
        idByCanonical[scan.module.canonical] = static_cast<std::uint32_t>(sources.size());
        s->names.push_back(id);
        sources.push_back(std::move(scan.module));
    }
    for (const auto& m : sources) {
        std::vector<std::uint32_t> deps;
        for (const auto& include : m.includes) {
            const auto found = idByCanonical.find(sc::canonicalPath(include, files));
            if (found == idByCanonical.end())
                fail("module " + m.path + " includes " + include + ", which is not in the library",
                     {sc::errorAt(m.path, 0, 0, "add " + include + " to the library's module files")});
            deps.push_back(found->second);
        }
        s->dependencies.push_back(std::move(deps));
        s->chunks.push_back({s->keep(m.text)});
    }
    checkCycles(sources, s->dependencies, settings, files);
    for (std::size_t i = 0; i < sources.size(); ++i)
        s->modules.push_back({s->keep(s->names[i]), s->keep(sources[i].path), s->keep(sources[i].description),
                              s->chunks[i], s->dependencies[i]});
    s->view = catalog::Catalog{{}, s->modules, s->attributes, s->uniforms, s->keep(std::move(versionDirective))};
    return s;
}

}  // namespace

ModuleLibrary::ModuleLibrary(std::unique_ptr<Storage> storage) : storage_(std::move(storage)) {}
ModuleLibrary::ModuleLibrary(ModuleLibrary&&) noexcept = default;
ModuleLibrary& ModuleLibrary::operator=(ModuleLibrary&&) noexcept = default;
ModuleLibrary::~ModuleLibrary() = default;

ModuleLibrary ModuleLibrary::fromFiles(std::span<const std::string> moduleFiles,
                                       std::span<const std::string> contractFiles, std::string versionDirective,
                                       std::span<const std::string> includeDirs) {
    return ModuleLibrary(build({moduleFiles.begin(), moduleFiles.end()}, {contractFiles.begin(), contractFiles.end()},
                               {includeDirs.begin(), includeDirs.end()}, sc::Files::disk(),
                               std::move(versionDirective)));
}

ModuleLibrary ModuleLibrary::fromStrings(std::span<const std::pair<std::string, std::string>> modules,
                                         std::string_view contractJson, std::string versionDirective,
                                         std::span<const std::string> includeDirs) {
    std::vector<std::pair<std::string, std::string>> texts(modules.begin(), modules.end());
    std::vector<std::string> paths;
    for (const auto& module : modules) paths.push_back(module.first);
    const std::string contractPath = "<contract>.json";
    texts.emplace_back(contractPath, std::string(contractJson));
    return ModuleLibrary(build(paths, {contractPath}, {includeDirs.begin(), includeDirs.end()},
                               sc::Files::memory(texts), std::move(versionDirective)));
}

const catalog::Catalog& ModuleLibrary::catalog() const {
    return storage_->view;
}

std::span<const std::string> ModuleLibrary::contractFiles() const {
    return storage_->contractFiles;
}

std::uint32_t ModuleLibrary::id(std::string_view name) const {
    std::vector<std::string> known;
    for (std::uint32_t i = 0; i < storage_->modules.size(); ++i) {
        if (storage_->modules[i].name == name) return i;
        known.emplace_back(storage_->modules[i].name);
    }
    throw CompositionError("prism module library: no module named '" + std::string(name) + "'" +
                           catalog::didYouMean(name, known) + "; the library has " +
                           (known.empty() ? "no modules" : catalog::nameList(known)));
}

}  // namespace prism::gl
