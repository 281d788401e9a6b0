// Resolves a composed stage's own source with the build step's resolver (see
// compose_includes.hpp): the catalogue's modules are served as in-memory files where the
// build step read them (under the source tree when one is given), so includes, cycles and
// #version conflicts are found, and reported, as prism-shaderc finds them.
#include "compose_includes.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>

#include "compose_check.hpp"

namespace prism::gl::detail {
namespace {

namespace sc = prism::shaderc;
namespace fs = std::filesystem;

// The folder a module's id is relative to: its path less one component per "__" part
// of the id ("modules/toon/quantize.glsl", "toon__quantize" -> "modules").
std::string rootOf(const catalog::Module& m) {
    fs::path root = fs::path(std::string(m.path)).lexically_normal();
    std::size_t parts = 1;
    for (std::size_t p = m.name.find("__"); p != std::string_view::npos; p = m.name.find("__", p + 2)) ++parts;
    for (std::size_t i = 0; i < parts && root.has_relative_path(); ++i) root = root.parent_path();
    return root.generic_string();
}

// The build step's -I and base dir: the tree's, else the roots of the modules' ids.
sc::ResolveSettings settingsFor(const catalog::Catalog& catalog, const catalog::SourceTree* tree,
                                std::span<const catalog::Define> defines) {
    sc::ResolveSettings settings;
    if (!catalog.versionDirective.empty()) settings.defaultVersion = std::string(catalog.versionDirective);
    for (const auto& d : defines) settings.defines.emplace_back(std::string(d.name), std::string(d.value));
    if (tree) {
        settings.includeDirs.assign(tree->moduleDirs.begin(), tree->moduleDirs.end());
        settings.baseDir = std::string(tree->baseDir);
        return settings;
    }
    for (const auto& m : catalog.modules) {
        const std::string root = rootOf(m);
        if (!m.path.empty() &&
            std::find(settings.includeDirs.begin(), settings.includeDirs.end(), root) == settings.includeDirs.end())
            settings.includeDirs.push_back(root);
    }
    return settings;
}

[[noreturn]] void fail(const std::string& sourceName, const std::vector<sc::Message>& messages) {
    throw compositionError("prism compose: " + sourceName + ": the build step's resolver rejected it", messages);
}

}  // namespace

std::string modulePathIn(const catalog::Module& m, const catalog::SourceTree* tree) {
    const std::string path = m.path.empty() ? std::string(m.name) : std::string(m.path);
    if (!tree || m.path.empty()) return path;
    const std::string_view dir =
        m.searchDir == 0 || m.searchDir > tree->moduleDirs.size() ? tree->baseDir : tree->moduleDirs[m.searchDir - 1];
    return (fs::path(std::string(dir)) / path).lexically_normal().generic_string();
}

std::vector<std::uint32_t> includedModules(const catalog::Catalog& catalog, const catalog::SourceTree* tree,
                                           const std::string& sourceName, std::string_view source,
                                           std::span<const catalog::Define> defines) {
    std::vector<std::pair<std::string, std::string>> texts{{sourceName, std::string(source)}};
    for (const auto& m : catalog.modules)
        if (!m.path.empty()) texts.emplace_back(modulePathIn(m, tree), catalog::joinChunks(m.chunks));
    const sc::Files files = sc::Files::memory(texts);
    std::map<std::string, std::uint32_t> idByCanonical;
    for (std::uint32_t id = 0; id < catalog.modules.size(); ++id)
        if (!catalog.modules[id].path.empty())
            idByCanonical.emplace(sc::canonicalPath(modulePathIn(catalog.modules[id], tree), files), id);

    const sc::StageResolution stage = sc::resolveStage(sourceName, settingsFor(catalog, tree, defines), files);
    if (!stage.ok || sc::hasError(stage.messages)) fail(sourceName, stage.messages);
    const std::string own = sc::canonicalPath(sourceName, files);
    std::vector<std::uint32_t> ids;
    for (const auto& file : stage.resolved.files) {  // source numbers: the stage, then what it includes
        const std::string canonical = sc::canonicalPath(file, files);
        if (canonical == own) continue;
        const auto found = idByCanonical.find(canonical);
        if (found == idByCanonical.end())
            fail(sourceName, {sc::errorAt(file, 0, 0,
                                          "included by " + sourceName +
                                              " but not a module of the catalogue; list it among the catalogue's "
                                              "modules")});
        ids.push_back(found->second);
    }
    return ids;
}

}  // namespace prism::gl::detail
