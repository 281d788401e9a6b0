// Orchestration of resolution and validation into a CatalogData (see catalog_builder.hpp).
#include "catalog_builder.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <set>
#include <thread>

#include "include_resolver.hpp"
#include "validator.hpp"
#include "variants.hpp"

namespace prism::shaderc {
namespace fs = std::filesystem;

namespace {

struct ModuleIndex {
    std::vector<CatalogModule> modules;
    std::map<std::string, std::uint32_t> byCanonical;
};

std::string moduleIdentifier(const fs::path& relative) {
    auto p = relative;
    p.replace_extension();
    std::string id;
    for (char c : p.generic_string()) id += (c == '/' || c == '.' || c == '-') ? '_' : c;
    return id;
}

// Every .glsl directly in the include dirs (not in subdirectories; the first directory
// wins for a shadowed name), plus any included file outside them.
ModuleIndex indexModules(const Options& o, const std::set<std::string>& extraFiles, const SourceReader& reader,
                         DiagnosticSink& sink) {
    ModuleIndex index;
    std::vector<std::pair<std::string, std::string>> found;  // identifier, path
    std::set<std::string> identifiers, canonicals;
    auto add = [&](const std::string& identifier, const std::string& path) {
        auto canonical = reader.canonical(path);
        if (!canonical || !canonicals.insert(*canonical).second) return;
        if (!identifiers.insert(identifier).second) {
            sink.report(makeError(
                path, 0, 0,
                "module identifier '" + identifier + "' is already taken by another module; rename one of them"));
            return;
        }
        found.emplace_back(identifier, path);
    };
    for (const auto& dir : o.includeDirs) {
        std::error_code ec;
        std::vector<fs::path> files;
        for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); ++it)
            if (it->is_regular_file() && it->path().extension() == ".glsl") files.push_back(it->path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) add(moduleIdentifier(f.lexically_relative(dir)), f.string());
    }
    for (const auto& f : extraFiles) add(moduleIdentifier(fs::path(f).filename()), f);
    std::sort(found.begin(), found.end());

    ResolveOptions ro{o.includeDirs, o.defines, {}};
    std::vector<std::vector<std::string>> includes;
    for (const auto& [identifier, path] : found) {
        auto scan = scanModule(path, ro, reader);
        sink.reportAll(scan.diagnostics);
        CatalogModule m{identifier, embeddedPath(path, o.baseDir), scan.module.description, scan.module.text, {}, path};
        index.byCanonical[*reader.canonical(path)] = static_cast<std::uint32_t>(index.modules.size());
        index.modules.push_back(std::move(m));
        includes.push_back(scan.module.includes);
    }
    for (std::size_t i = 0; i < index.modules.size(); ++i)
        for (const auto& inc : includes[i])
            if (auto c = reader.canonical(inc); c && index.byCanonical.count(*c))
                index.modules[i].dependencies.push_back(index.byCanonical[*c]);
    return index;
}

std::string versionDirective(int version, const std::string& profile) {
    return "#version " + std::to_string(version) + (profile.empty() ? "" : " " + profile);
}

}  // namespace

ResolvedCatalog resolveCatalog(const Options& o, const std::vector<ShaderInput>& shaders, const Contract& contract,
                               const SourceReader& reader, DiagnosticSink& sink) {
    ResolvedCatalog rc;
    rc.data.nameSpace = o.nameSpace;
    rc.data.contract = contract;
    rc.data.versionDirective = versionDirective(o.glslVersion, o.glslProfile);
    for (const auto& f : contract.files) rc.filesRead.push_back(f);

    auto filters = parseVariantFilters(o.variantFilters);
    sink.reportAll(filters.diagnostics);
    std::set<std::string> includedCanonical;
    std::map<std::string, std::string> includedPath;  // canonical -> display

    for (const auto& shader : shaders) {
        ResolveOptions base{o.includeDirs, o.defines, rc.data.versionDirective};
        std::vector<VariantPragma> pragmas;
        bool ok = true;
        std::vector<std::string> stagePaths;
        for (const auto& st : shader.stages) {
            auto r = resolveStage(st.path, base, reader);
            sink.reportAll(r.diagnostics);
            ok = ok && r.ok;
            pragmas.insert(pragmas.end(), r.stage.variantPragmas.begin(), r.stage.variantPragmas.end());
            stagePaths.push_back(st.path);
        }
        if (!ok) continue;
        auto axes = axesFromPragmas(pragmas);
        sink.reportAll(axes.diagnostics);
        auto choices = variantChoices(shader.name, axes.axes, filters.filters);
        sink.reportAll(choices.diagnostics);
        if (!axes.diagnostics.empty() || !choices.diagnostics.empty()) continue;

        CatalogShader cs{shader.name, axes.axes, {}, {}};
        std::vector<std::vector<ResolvedStage>> resolvedVariants;
        for (const auto& choice : choices.choices) {
            ResolveOptions vo = base;
            vo.defines.insert(vo.defines.end(), choice.defines.begin(), choice.defines.end());
            CatalogVariant cv{choice.name, choice.defines, {}, {}};
            std::vector<ResolvedStage> stages;
            for (const auto& st : shader.stages) {
                auto r = resolveStage(st.path, vo, reader);
                sink.reportAll(r.diagnostics);
                ok = ok && r.ok;
                CatalogStage cst{st.stage, r.stage.text, {}};
                for (const auto& f : r.stage.files) {
                    cst.files.push_back(embeddedPath(f.path, o.baseDir));
                    if (f.number > 0 && includedCanonical.insert(f.canonical).second)
                        includedPath[f.canonical] = f.path;
                }
                rc.filesRead.insert(rc.filesRead.end(), r.stage.filesRead.begin(), r.stage.filesRead.end());
                cv.stages.push_back(std::move(cst));
                stages.push_back(std::move(r.stage));
            }
            cs.variants.push_back(std::move(cv));
            resolvedVariants.push_back(std::move(stages));
        }
        if (!ok) continue;
        rc.data.shaders.push_back(std::move(cs));
        rc.resolved.push_back(std::move(resolvedVariants));
        rc.stagePaths.push_back(std::move(stagePaths));
    }

    // A "*" filter must name axes that some shader declares, or it is a typo.
    for (const auto& f : filters.filters) {
        if (f.shader != "*") continue;
        for (const auto& [name, value] : f.fixed) {
            bool declared = false;
            for (const auto& cs : rc.data.shaders)
                for (const auto& axis : cs.axes) declared = declared || axis.name == name;
            if (!declared)
                sink.report(makeError(
                    "", 0, 0, "--variant *:" + name + "=" + value + ": no shader declares a variant '" + name + "'"));
        }
    }

    // Modules: the include dirs' .glsl files plus anything included from elsewhere.
    std::set<std::string> extra;
    for (const auto& [canonical, path] : includedPath) {
        bool inDirs = false;
        for (const auto& dir : o.includeDirs)
            if (auto c = reader.canonical(dir); c && canonical.rfind(*c + "/", 0) == 0) inDirs = true;
        if (!inDirs) extra.insert(path);
    }
    auto modules = indexModules(o, extra, reader, sink);
    for (const auto& m : modules.modules) rc.filesRead.push_back(m.sourcePath);
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        std::set<std::uint32_t> used;
        for (const auto& variant : rc.resolved[s])
            for (const auto& stage : variant)
                for (const auto& f : stage.files)
                    if (auto it = modules.byCanonical.find(f.canonical);
                        f.number > 0 && it != modules.byCanonical.end())
                        used.insert(it->second);
        rc.data.shaders[s].modules.assign(used.begin(), used.end());
    }
    rc.data.modules = std::move(modules.modules);
    return rc;
}

void validateCatalog(ResolvedCatalog& rc, const Contract& contract, int jobs, DiagnosticSink& sink) {
    struct Task {
        std::size_t shader, variant;
    };
    std::vector<Task> tasks;
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s)
        for (std::size_t v = 0; v < rc.data.shaders[s].variants.size(); ++v) tasks.push_back({s, v});
    std::vector<ValidatedVariant> results(tasks.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < tasks.size();) {
            const auto& t = tasks[i];
            std::vector<StageToValidate> stages;
            const auto& resolvedStages = rc.resolved[t.shader][t.variant];
            for (std::size_t st = 0; st < resolvedStages.size(); ++st)
                stages.push_back({rc.data.shaders[t.shader].variants[t.variant].stages[st].stage,
                                  rc.stagePaths[t.shader][st], resolvedStages[st]});
            results[i] = validateProgram(stages, contract);
        }
    };
    const std::size_t threads =
        std::clamp<std::size_t>(static_cast<std::size_t>(jobs), 1, std::max<std::size_t>(1, tasks.size()));
    std::vector<std::thread> pool;
    for (std::size_t i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();

    for (std::size_t i = 0; i < tasks.size(); ++i) {
        auto& variant = rc.data.shaders[tasks[i].shader].variants[tasks[i].variant];
        for (auto& d : results[i].diagnostics) {
            if (rc.data.shaders[tasks[i].shader].variants.size() > 1 && d.severity == Severity::Error)
                d.notes.push_back(
                    {Severity::Note,
                     "",
                     0,
                     0,
                     "in variant " + variant.name + " of shader '" + rc.data.shaders[tasks[i].shader].name + "'",
                     {},
                     {}});
            sink.report(std::move(d));
        }
        variant.reflection = std::move(results[i].reflection);
    }
}

std::string fingerprint(const ResolvedCatalog& rc) {
    // FNV-1a over the resolved texts, paths and everything else the header prints.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](std::string_view s) {
        for (unsigned char c : s) {
            h ^= c;
            h *= 1099511628211ull;
        }
        h ^= 0xff;
        h *= 1099511628211ull;
    };
    const auto& d = rc.data;
    mix(PRISM_VERSION);
    mix(d.nameSpace);
    mix(d.commandLine);
    mix(d.versionDirective);  // the banner shows the command
    for (const auto& s : d.shaders) {
        mix(s.name);
        for (const auto& a : s.axes) {
            mix(a.name);
            for (const auto& v : a.values) mix(v);
        }
        for (const auto& v : s.variants)
            for (const auto& st : v.stages) {
                mix(st.text);
                for (const auto& f : st.files) mix(f);
            }
        for (auto m : s.modules) mix(std::to_string(m));
    }
    for (const auto& m : d.modules) {
        mix(m.identifier);
        mix(m.path);
        mix(m.description);
        mix(m.text);
        for (auto dep : m.dependencies) mix(std::to_string(dep));
    }
    for (const auto& a : d.contract.attributes) {
        mix(a.name);
        mix(a.type);
        mix(std::to_string(a.location));
    }
    for (const auto& u : d.contract.uniforms) {
        mix(u.name);
        mix(u.type);
        mix(std::to_string(u.array));
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace prism::shaderc
