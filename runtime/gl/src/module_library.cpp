// Module libraries read at run time through the shader tool's stages (see
// prism/gl/module_library.hpp).
#include "prism/gl/module_library.hpp"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <map>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "include_resolver.hpp"
#include "prism/catalog/did_you_mean.hpp"
#include "prism/gl/compose.hpp"
#include "source_reader.hpp"

namespace prism::gl {

struct ModuleLibrary::Storage {
    std::deque<std::string> strings;  // every name, path, description and text the views point into
    std::vector<std::vector<std::string_view>> chunks;
    std::vector<std::vector<std::uint32_t>> dependencies;
    std::vector<catalog::Module> modules;
    std::vector<catalog::Attribute> attributes;
    std::vector<catalog::Uniform> uniforms;
    catalog::Catalog view{};

    std::string_view keep(std::string s) { return strings.emplace_back(std::move(s)); }
};

namespace {

[[noreturn]] void fail(const std::string& what, const std::vector<shaderc::Diagnostic>& diagnostics) {
    std::vector<std::string> lines;
    std::string message = "prism module library: " + what;
    for (const auto& d : diagnostics) {
        lines.push_back(shaderc::formatDiagnostic(d, shaderc::ErrorFormat::Gcc));
        message += "\n" + lines.back();
    }
    throw CompositionError(message, lines);
}

std::unique_ptr<ModuleLibrary::Storage> build(const std::vector<std::string>& moduleFiles,
                                              const std::vector<std::string>& contractFiles,
                                              const shaderc::SourceReader& reader, std::string versionDirective) {
    auto s = std::make_unique<ModuleLibrary::Storage>();
    const auto contract = shaderc::loadContracts(contractFiles, reader);
    if (contract.ioError || !contract.diagnostics.empty()) fail("the contract could not be read", contract.diagnostics);
    for (const auto& a : contract.contract.attributes)
        s->attributes.push_back({s->keep(a.name), shaderc::glTypeOf(a.type), a.location});
    for (const auto& u : contract.contract.uniforms)
        s->uniforms.push_back({s->keep(u.name), shaderc::glTypeOf(u.type), u.array > 0 ? u.array : 1});

    shaderc::ResolveOptions options;
    for (const auto& f : moduleFiles) {
        std::string dir = shaderc::parentDir(f);
        if (std::find(options.includeDirs.begin(), options.includeDirs.end(), dir) == options.includeDirs.end())
            options.includeDirs.push_back(dir);
    }
    std::map<std::string, std::uint32_t> idByCanonical;
    std::vector<shaderc::ModuleSource> sources;
    for (const auto& f : moduleFiles) {
        auto scan = shaderc::scanModule(f, options, reader);
        if (!scan.ok) fail("module " + f + " could not be read", scan.diagnostics);
        idByCanonical[scan.module.canonical] = static_cast<std::uint32_t>(sources.size());
        sources.push_back(std::move(scan.module));
    }
    for (const auto& m : sources) {
        std::vector<std::uint32_t> deps;
        for (const auto& include : m.includes) {
            const auto canonical = reader.canonical(include);
            const auto found = canonical ? idByCanonical.find(*canonical) : idByCanonical.end();
            if (found == idByCanonical.end())
                fail("module " + m.path + " includes " + include + ", which is not in the library",
                     {shaderc::makeError(m.path, 0, 0, "add " + include + " to the library's module files")});
            deps.push_back(found->second);
        }
        s->dependencies.push_back(std::move(deps));
        s->chunks.push_back({s->keep(m.text)});
    }
    for (std::size_t i = 0; i < sources.size(); ++i) {
        const std::string name = std::filesystem::path(sources[i].path).stem().string();
        s->modules.push_back({s->keep(name), s->keep(sources[i].path), s->keep(sources[i].description), s->chunks[i],
                              s->dependencies[i]});
    }
    s->view = catalog::Catalog{{}, s->modules, s->attributes, s->uniforms, s->keep(std::move(versionDirective))};
    return s;
}

}  // namespace

ModuleLibrary::ModuleLibrary(std::unique_ptr<Storage> storage) : storage_(std::move(storage)) {}
ModuleLibrary::ModuleLibrary(ModuleLibrary&&) noexcept = default;
ModuleLibrary& ModuleLibrary::operator=(ModuleLibrary&&) noexcept = default;
ModuleLibrary::~ModuleLibrary() = default;

ModuleLibrary ModuleLibrary::fromFiles(std::span<const std::string> moduleFiles,
                                       std::span<const std::string> contractFiles, std::string versionDirective) {
    shaderc::DiskReader reader;
    return ModuleLibrary(build({moduleFiles.begin(), moduleFiles.end()}, {contractFiles.begin(), contractFiles.end()},
                               reader, std::move(versionDirective)));
}

ModuleLibrary ModuleLibrary::fromStrings(std::span<const std::pair<std::string, std::string>> modules,
                                         std::string_view contractJson, std::string versionDirective) {
    shaderc::MemoryReader reader;
    std::vector<std::string> paths;
    for (const auto& [path, text] : modules) {
        reader.add(path, text);
        paths.push_back(path);
    }
    const std::string contractPath = "<contract>.json";
    reader.add(contractPath, std::string(contractJson));
    return ModuleLibrary(build(paths, {contractPath}, reader, std::move(versionDirective)));
}

const catalog::Catalog& ModuleLibrary::catalog() const {
    return storage_->view;
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
