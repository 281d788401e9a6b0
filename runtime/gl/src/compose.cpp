// Module dependency ordering and source layout for run-time composed programs.
#include "prism/gl/compose.hpp"

#include <cctype>

#include <prism/catalog/line_directive.hpp>

#include "compose_check.hpp"
#include "compose_includes.hpp"
#include "prism/gl/module_library.hpp"

namespace prism::gl {
namespace {

constexpr std::string_view kDefaultVersion = "#version 330 core";

std::string_view versionDirectiveOf(const catalog::Catalog& c) {
    return c.versionDirective.empty() ? kDefaultVersion : c.versionDirective;
}

const catalog::Module& moduleAt(const catalog::Catalog& c, std::uint32_t id) {
    if (id >= c.modules.size())
        throw CompositionError("prism compose: module id " + std::to_string(id) + " is not in the catalogue (it has " +
                               std::to_string(c.modules.size()) + " modules)");
    return c.modules[id];
}

std::string_view shownPath(const catalog::Module& m) {
    return m.path.empty() ? m.name : m.path;
}

// The build step's include cycle error, at the module whose dependency closes the cycle (a
// catalogue keeps no line numbers of its modules' #includes).
CompositionError cycleError(const catalog::Catalog& c, const std::vector<std::uint32_t>& cycle) {
    std::string chain;
    for (std::uint32_t id : cycle) chain += std::string(shownPath(c.modules[id])) + " -> ";
    chain += shownPath(c.modules[cycle.front()]);
    const shaderc::Message message =
        shaderc::errorAt(std::string(shownPath(c.modules[cycle.back()])), 0, 0,
                         "include cycle: " + chain + "; add an include guard or #pragma once, or break the cycle");
    return detail::compositionError("prism compose: module dependency cycle", std::span(&message, 1));
}

void visit(const catalog::Catalog& c, std::uint32_t id, std::vector<std::uint32_t>& path, std::vector<char>& done,
           std::vector<std::uint32_t>& out) {
    const catalog::Module& m = moduleAt(c, id);
    if (done[id]) return;
    for (std::size_t i = 0; i < path.size(); ++i)
        if (path[i] == id) throw cycleError(c, {path.begin() + static_cast<std::ptrdiff_t>(i), path.end()});
    path.push_back(id);
    for (std::uint32_t dep : m.dependencies) visit(c, dep, path, done, out);
    path.pop_back();
    done[id] = 1;
    out.push_back(id);
}

std::string_view trimmedStart(std::string_view line) {
    std::size_t p = 0;
    while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
    return line.substr(p);
}

// True when `line` is a preprocessor directive named `name` ("# version" allowed).
bool isDirective(std::string_view line, std::string_view name) {
    std::string_view t = trimmedStart(line);
    if (t.empty() || t[0] != '#') return false;
    t = trimmedStart(t.substr(1));
    return t.substr(0, name.size()) == name &&
           (t.size() == name.size() || !std::isalnum(static_cast<unsigned char>(t[name.size()])));
}

// A source (yours, or a module's own text) with its #version and #include lines blanked
// (line numbers kept; the includes join the modules) and its first #version line, which
// the build step keeps for a stage.
struct UserText {
    std::string text;
    std::string version;  // "" when the source has none
    bool includes = false;
};

UserText userText(std::string_view source) {
    UserText out;
    std::size_t start = 0;
    while (start <= source.size()) {
        std::size_t end = source.find('\n', start);
        if (end == std::string_view::npos) end = source.size();
        const std::string_view line = source.substr(start, end - start);
        const bool version = isDirective(line, "version"), include = isDirective(line, "include");
        if (version && out.version.empty()) out.version = trimmedStart(line);
        out.includes = out.includes || include;
        if (!version && !include) out.text.append(line);
        if (end < source.size()) out.text += '\n';
        start = end + 1;
    }
    if (!out.text.empty() && out.text.back() != '\n') out.text += '\n';
    return out;
}

}  // namespace

std::vector<std::uint32_t> moduleOrder(const catalog::Catalog& catalog, std::span<const std::uint32_t> wanted) {
    std::vector<std::uint32_t> out, path;
    std::vector<char> done(catalog.modules.size(), 0);
    for (std::uint32_t id : wanted) visit(catalog, id, path, done, out);
    return out;
}

namespace {

// composeStage, with the modules placed where `tree` (may be null) says the build step read them.
StageText composeStageIn(const catalog::Catalog& catalog, const catalog::SourceTree* tree, const ComposeStage& stage,
                         std::span<const catalog::Define> defines) {
    StageText text;
    text.stage = stage.stage;
    const std::string userName =
        stage.sourceName.empty() ? "<composed " + std::string(catalog::stageName(stage.stage)) + ">" : stage.sourceName;
    const UserText user = userText(stage.source);
    std::vector<std::uint32_t> modules = stage.modules;
    if (user.includes)
        for (std::uint32_t id : detail::includedModules(catalog, tree, userName, stage.source, defines))
            modules.push_back(id);
    const std::string versionLine = user.version.empty() ? std::string(versionDirectiveOf(catalog)) : user.version;
    // Each file starts at its line 1 (the `#line` rule: prism/catalog/line_directive.hpp).
    const auto version = catalog::glslVersionOf(versionLine);

    std::string& src = text.source;
    src.append(versionLine);
    src += '\n';
    for (const auto& d : defines) {
        src += "#define ";
        src.append(d.name);
        if (!d.value.empty()) {
            src += ' ';
            src.append(d.value);
        }
        src += '\n';
    }
    text.files.push_back({0, userName});

    std::uint32_t number = 1;
    for (std::uint32_t id : moduleOrder(catalog, modules)) {
        const catalog::Module& m = catalog.modules[id];
        src += catalog::lineDirective(1, number, version) + '\n';
        src += userText(catalog::joinChunks(m.chunks)).text;  // its #version blanked: the stage has one, on line 1
        text.files.push_back({number, detail::modulePathIn(m, tree)});
        ++number;
    }
    src += catalog::lineDirective(1, 0, version) + '\n';
    src += user.text;
    return text;
}

ProgramSources composeSourcesIn(const catalog::Catalog& catalog, const catalog::SourceTree* tree,
                                std::span<const ComposeStage> stages, std::string label,
                                std::span<const catalog::Define> defines) {
    ProgramSources out;
    out.label = std::move(label);
    for (const auto& s : stages) out.stages.push_back(composeStageIn(catalog, tree, s, defines));
    for (const auto& a : catalog.contractAttributes) out.attributes.push_back({std::string(a.name), a.location});
    return out;
}

}  // namespace

StageText composeStage(const catalog::Catalog& catalog, const ComposeStage& stage,
                       std::span<const catalog::Define> defines) {
    return composeStageIn(catalog, nullptr, stage, defines);
}

ProgramSources composeSources(const catalog::Catalog& catalog, std::span<const ComposeStage> stages, std::string label,
                              std::span<const catalog::Define> defines) {
    return composeSourcesIn(catalog, nullptr, stages, std::move(label), defines);
}

namespace {

Program checkedProgram(const catalog::Catalog& catalog, const catalog::SourceTree* tree,
                       std::span<const ComposeStage> stages, std::string label,
                       std::span<const catalog::Define> defines, std::span<const std::string> contractFiles) {
    ProgramSources sources = composeSourcesIn(catalog, tree, stages, std::move(label), defines);
    const std::vector<std::string> problems = detail::checkComposedSources(catalog, sources, contractFiles);
    if (!problems.empty()) {
        std::string message = "prism compose: " + sources.label + " failed the build step's checks:";
        for (const auto& p : problems) message += "\n" + p;
        throw CompositionError(message, problems);
    }
    return Program(std::move(sources));
}

}  // namespace

Program composeProgram(const catalog::Catalog& catalog, std::span<const ComposeStage> stages, std::string label,
                       std::span<const catalog::Define> defines) {
    // The contract files as the build step embedded them (relative, like the modules' paths).
    std::vector<std::string> files;
    for (const auto& f : catalog.contractFiles) files.emplace_back(f.path);
    if (files.empty()) files.emplace_back("the catalogue's binding contract (prism-shaderc --contract)");
    return checkedProgram(catalog, nullptr, stages, std::move(label), defines, files);
}

Program composeProgram(const catalog::Catalog& catalog, const catalog::SourceTree& tree,
                       std::span<const ComposeStage> stages, std::string label,
                       std::span<const catalog::Define> defines) {
    const std::vector<std::string> files(tree.contractFiles.begin(), tree.contractFiles.end());
    return checkedProgram(catalog, &tree, stages, std::move(label), defines, files);
}

Program composeProgram(const ModuleLibrary& library, std::span<const ComposeStage> stages, std::string label,
                       std::span<const catalog::Define> defines) {
    return checkedProgram(library.catalog(), nullptr, stages, std::move(label), defines, library.contractFiles());
}

}  // namespace prism::gl
