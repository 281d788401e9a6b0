// Resolves a composed stage's #include lines with the build step's resolver (see
// compose_includes.hpp): the catalogue's modules are served as in-memory files at their
// paths, under the roots their ids are relative to.
#include "compose_includes.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "compose_check.hpp"

namespace prism::gl::detail {
namespace {

namespace sc = prism::shaderc;

// The folder a module's id is relative to: its path less one component per "__" part
// of the id ("modules/toon/quantize.glsl", "toon__quantize" -> "modules").
std::string rootOf(const catalog::Module& m) {
    std::filesystem::path root = std::filesystem::path(std::string(m.path)).lexically_normal();
    std::size_t parts = 1;
    for (std::size_t p = m.name.find("__"); p != std::string_view::npos; p = m.name.find("__", p + 2)) ++parts;
    for (std::size_t i = 0; i < parts && root.has_relative_path(); ++i) root = root.parent_path();
    return root.generic_string();
}

[[noreturn]] void fail(const std::string& sourceName, const std::vector<sc::Message>& messages) {
    throw compositionError("prism compose: " + sourceName + ": an #include could not be resolved", messages);
}

}  // namespace

std::vector<std::uint32_t> includedModules(const catalog::Catalog& catalog, const std::string& sourceName,
                                           std::string_view source, std::span<const catalog::Define> defines) {
    std::vector<std::pair<std::string, std::string>> texts{{sourceName, std::string(source)}};
    sc::ResolveSettings settings;
    for (const auto& d : defines) settings.defines.emplace_back(std::string(d.name), std::string(d.value));
    for (const auto& m : catalog.modules) {
        if (m.path.empty()) continue;
        texts.emplace_back(std::string(m.path), catalog::joinChunks(m.chunks));
        const std::string root = rootOf(m);
        if (std::find(settings.includeDirs.begin(), settings.includeDirs.end(), root) == settings.includeDirs.end())
            settings.includeDirs.push_back(root);
    }
    const sc::Files files = sc::Files::memory(texts);
    const sc::ModuleScan scan = sc::scanModule(sourceName, settings, files);
    if (!scan.ok || sc::hasError(scan.messages)) fail(sourceName, scan.messages);
    std::vector<std::uint32_t> ids;
    for (const auto& include : scan.module.includes) {
        const std::string canonical = sc::canonicalPath(include, files);
        std::uint32_t id = 0;
        while (id < catalog.modules.size() &&
               sc::canonicalPath(std::string(catalog.modules[id].path), files) != canonical)
            ++id;
        if (id == catalog.modules.size())
            fail(sourceName, {sc::errorAt(include, 0, 0,
                                          "included by " + sourceName +
                                              " but not a module of the catalogue; list it among "
                                              "the catalogue's modules")});
        ids.push_back(id);
    }
    return ids;
}

}  // namespace prism::gl::detail
