// The resolution stage as its phases, resolveBaseRuns to attachModules (see catalog_builder.hpp).
#include "catalog_builder.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>

#include "generated_format.hpp"
#include "include_resolver.hpp"
#include "job_pool.hpp"
#include "module_naming.hpp"
#include "prism/hash/content_hash.hpp"
#include "shown_path.hpp"
#include "source_fingerprint.hpp"
#include "variant_resolution.hpp"
#include "variants.hpp"

namespace prism::shaderc {
namespace fs = std::filesystem;

namespace {

struct ModuleIndex {
    std::vector<CatalogModule> modules;
    std::map<std::string, std::uint32_t> byCanonical;
};

struct ModuleFile {
    std::string path;       // as read
    std::string canonical;  // identity
};

// The folders module names are relative to, in order: the -I directories, the stage
// folders, then --base-dir.
std::vector<std::string> namingRoots(const Options& o, const std::vector<ShaderInput>& shaders,
                                     const SourceReader& reader) {
    std::vector<std::string> roots;
    auto add = [&](const std::string& dir) {
        std::error_code ec;
        const auto canonical = fs::weakly_canonical(dir.empty() ? "." : dir, ec);
        if (ec) return;
        std::string text = canonical.generic_string();
        while (text.size() > 1 && text.back() == '/') text.pop_back();
        if (std::find(roots.begin(), roots.end(), text) == roots.end()) roots.push_back(text);
    };
    for (const auto& dir : o.includeDirs) add(dir);
    for (const auto& shader : shaders)
        for (const auto& stage : shader.stages)
            if (auto c = reader.canonical(stage.path)) add(parentDir(*c));
    add(o.baseDir);
    return roots;
}

// The module's path relative to the first root holding it (else its full path).
std::string namingPath(const std::string& canonical, const std::vector<std::string>& roots) {
    for (const auto& root : roots) {
        const std::string prefix = root == "/" ? root : root + "/";
        if (canonical.starts_with(prefix)) return canonical.substr(prefix.size());
    }
    return canonical;
}

// A module that an earlier include dir's module of the same name hides: `#include "name"`
// never finds it, so it is not in the catalogue unless a stage includes it by another path.
Diagnostic shadowedModuleWarning(const fs::path& hidden, const std::string& winner) {
    Diagnostic d = makeError(hidden.string(), 0, 0,
                             "module '" + hidden.filename().string() + "' is shadowed by " + winner +
                                 " (an earlier include dir): #include \"" + hidden.filename().string() +
                                 "\" finds that one, and this file is left out of the catalogue; rename one of "
                                 "them, or drop one folder from the include dirs");
    d.severity = Severity::Warning;
    return d;
}

// Every .glsl directly in the include dirs (the first directory wins for a shadowed
// name, and the hidden one is a warning), plus every included file elsewhere (in their
// subfolders too).
std::vector<ModuleFile> moduleFiles(const Options& o, const std::vector<std::string>& includedFiles,
                                    const SourceReader& reader, DiagnosticSink& sink) {
    std::vector<ModuleFile> files;
    std::set<std::string> canonicals;
    std::map<std::string, std::string> firstByName;  // file name -> the path that wins
    auto add = [&](const std::string& path) {
        auto canonical = reader.canonical(path);
        if (canonical && canonicals.insert(*canonical).second) files.push_back({path, *canonical});
    };
    for (const auto& dir : o.includeDirs) {
        std::error_code ec;
        std::vector<fs::path> found;
        for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
            if (it->is_regular_file(ec) && it->path().extension() == ".glsl") found.push_back(it->path());
        std::sort(found.begin(), found.end());
        for (const auto& f : found) {
            const auto [winner, first] = firstByName.emplace(f.filename().string(), f.string());
            if (first)
                add(f.string());
            else if (reader.canonical(f.string()) != reader.canonical(winner->second))
                sink.report(shadowedModuleWarning(f, winner->second));
        }
    }
    for (const auto& f : includedFiles) add(f);
    return files;
}

// Each file's module identifier with its index into `files`, sorted by identifier.
std::vector<std::pair<std::string, std::size_t>> moduleNames(const Options& o, const std::vector<ShaderInput>& shaders,
                                                             const std::vector<ModuleFile>& files,
                                                             const SourceReader& reader, DiagnosticSink& sink) {
    const auto roots = namingRoots(o, shaders, reader);
    std::vector<std::pair<std::string, std::size_t>> named;
    std::set<std::string> identifiers;
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::string id = mangleModulePath(namingPath(files[i].canonical, roots));
        if (identifiers.contains(id)) {
            // Only possible for equal paths under two roots: name it by its path from --base-dir.
            const std::string first = id;
            id = mangleModulePath(shownPath(files[i].canonical, o));
            for (int n = 2; identifiers.contains(id); ++n) id = first + "__" + std::to_string(n);
            Diagnostic note = makeError(
                files[i].path, 0, 0,
                "module name '" + first + "' is taken by a module under an earlier root; this one is '" + id + "'");
            note.severity = Severity::Warning;
            sink.report(std::move(note));
        }
        identifiers.insert(id);
        named.emplace_back(id, i);
    }
    std::sort(named.begin(), named.end());
    return named;
}

// A module of a library: found through an -I folder outside --base-dir (the project), so
// its comments are not the project's to fix.
bool isLibraryModule(const std::string& path, const Options& o) {
    return embeddedLocation(path, o).searchDir != 0;
}

// A scan's diagnostics. Errors in a module no stage includes are warnings: only what is
// used fails a build (used modules show their errors in the stages, under their macros).
void reportScan(ModuleScanResult& scan, const std::string& identifier, bool used, DiagnosticSink& sink) {
    for (auto& d : scan.diagnostics) {
        if (d.severity != Severity::Error) {
            sink.report(std::move(d));
        } else if (!used) {
            d.severity = Severity::Warning;
            d.message += " (in module " + identifier + ", which no stage includes, so a warning)";
            sink.report(std::move(d));
        }
    }
}

// The modules of moduleFiles(), named, scanned (on -j threads, a thread per 64 modules at
// most) and reported in name order, with their dependencies.
ModuleIndex indexModules(const Options& o, const std::vector<ShaderInput>& shaders,
                         const std::vector<std::string>& includedFiles, const std::set<std::string>& used,
                         const SourceReader& reader, DiagnosticSink& sink) {
    const auto files = moduleFiles(o, includedFiles, reader, sink);
    const auto named = moduleNames(o, shaders, files, reader, sink);
    const ResolveOptions ro{o.includeDirs, o.defines, {}, o.baseDir};
    std::vector<ModuleScanResult> scans(named.size());
    const int jobs = std::clamp(o.jobs, 1, static_cast<int>(std::max<std::size_t>(1, named.size() / 64)));
    runPool(named.size(), jobs, [&](std::size_t i) {
        const std::string& path = files[named[i].second].path;
        ResolveOptions mo = ro;
        mo.warnUndocumentedModule = o.warnUndocumentedLibraryModules || !isLibraryModule(path, o);
        scans[i] = scanModule(path, mo, reader);
    });

    ModuleIndex index;
    std::vector<std::vector<std::string>> includes;
    for (std::size_t n = 0; n < named.size(); ++n) {
        const auto& [identifier, fileIndex] = named[n];
        const ModuleFile& file = files[fileIndex];
        reportScan(scans[n], identifier, used.contains(file.canonical), sink);
        index.byCanonical[file.canonical] = static_cast<std::uint32_t>(index.modules.size());
        const auto where = embeddedLocation(file.path, o);
        index.modules.push_back({identifier,
                                 where.path,
                                 scans[n].module.description,
                                 scans[n].module.text,
                                 {},
                                 file.path,
                                 where.searchDir});
        includes.push_back(scans[n].module.includes);
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

// The files stages included (source number > 0), by canonical path, with a path to read them by.
struct IncludedFiles {
    std::map<std::string, std::string> pathOf;  // canonical -> display
    void add(const ResolvedFile& f) {
        if (f.number > 0) pathOf.try_emplace(f.canonical, f.path);
    }
};

// Phase 1: every stage once with the base options (no variant defines), on -j threads.
// These runs find the variant axes, and variants share them where they can.
std::vector<std::vector<ResolveResult>> resolveBaseRuns(const Options& o, const std::vector<ShaderInput>& shaders,
                                                        const ResolveOptions& base, const SourceReader& reader) {
    std::vector<std::pair<std::size_t, std::size_t>> allStages;  // (shader, stage)
    for (std::size_t s = 0; s < shaders.size(); ++s)
        for (std::size_t st = 0; st < shaders[s].stages.size(); ++st) allStages.emplace_back(s, st);
    std::vector<std::vector<ResolveResult>> baseRuns(shaders.size());
    for (std::size_t s = 0; s < shaders.size(); ++s) baseRuns[s].resize(shaders[s].stages.size());
    runPool(allStages.size(), o.jobs, [&](std::size_t i) {
        const auto [s, st] = allStages[i];
        baseRuns[s][st] = resolveStage(shaders[s].stages[st].path, base, reader);
    });
    return baseRuns;
}

// A shader's axes and variant choices, from its base runs.
struct ShaderPlan {
    std::vector<Diagnostic> diagnostics;  // reported in this order, before the variants'
    bool ok = true;
    std::vector<std::string> stagePaths;
    std::vector<Axis> axes;
    std::vector<VariantChoice> choices;
    std::vector<std::vector<ResolveResult>> resolved;  // [variant][stage]
};

// Phase 2: one shader's plan. Its base runs' files count as included even when a stage
// fails, so that no module it uses is called one "no stage includes".
ShaderPlan planShader(const ShaderInput& shader, const std::vector<ResolveResult>& baseRuns,
                      const std::vector<VariantFilter>& filters, IncludedFiles& included) {
    ShaderPlan plan;
    std::vector<VariantPragma> pragmas;
    for (const auto& r : baseRuns) {
        plan.diagnostics.insert(plan.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
        plan.ok = plan.ok && r.ok;
        for (const auto& f : r.stage.files) included.add(f);
        pragmas.insert(pragmas.end(), r.stage.variantPragmas.begin(), r.stage.variantPragmas.end());
        plan.stagePaths.push_back(shader.stages[plan.stagePaths.size()].path);
    }
    if (!plan.ok) return plan;
    auto axes = axesFromPragmas(pragmas);
    plan.diagnostics.insert(plan.diagnostics.end(), axes.diagnostics.begin(), axes.diagnostics.end());
    auto choices = variantChoices(shader.name, axes.axes, filters);
    plan.diagnostics.insert(plan.diagnostics.end(), choices.diagnostics.begin(), choices.diagnostics.end());
    plan.ok = axes.diagnostics.empty() && choices.diagnostics.empty();
    plan.axes = std::move(axes.axes);
    plan.choices = std::move(choices.choices);
    return plan;
}

// Phase 3: the planned shaders' variants, several shaders at once (each on -j / shaders
// threads), sharing runs unless --no-variant-sharing.
void resolvePlannedVariants(const Options& o, const ResolveOptions& base, std::vector<ShaderPlan>& plans,
                            const std::vector<std::vector<ResolveResult>>& baseRuns, const SourceReader& reader) {
    std::vector<std::size_t> toResolve;
    for (std::size_t s = 0; s < plans.size(); ++s)
        if (plans[s].ok) toResolve.push_back(s);
    const int innerJobs = std::max(1, o.jobs / std::max(1, static_cast<int>(toResolve.size())));
    runPool(toResolve.size(), o.jobs, [&](std::size_t i) {
        ShaderPlan& plan = plans[toResolve[i]];
        plan.resolved = resolveVariants(plan.stagePaths, base, plan.choices, reader, innerJobs, baseRuns[toResolve[i]],
                                        !o.noVariantSharing);
    });
}

// Phase 4: one shader of the catalogue from its resolved plan, reporting its diagnostics
// in order; false when a variant failed.
bool assembleShader(const Options& o, const ShaderInput& shader, ShaderPlan& plan, IncludedFiles& included,
                    std::map<std::string, EmbeddedPath>& shownPaths, ResolvedCatalog& rc, DiagnosticSink& sink) {
    bool ok = true;
    CatalogShader cs{shader.name, plan.axes, {}, {}};
    std::vector<std::vector<ResolvedStage>> resolvedVariants;
    for (std::size_t vi = 0; vi < plan.choices.size(); ++vi) {
        CatalogVariant cv{plan.choices[vi].name, plan.choices[vi].defines, {}, {}};
        std::vector<ResolvedStage> stages;
        for (std::size_t si = 0; si < shader.stages.size(); ++si) {
            auto r = std::move(plan.resolved[vi][si]);
            rc.preprocessorRuns += !r.stage.shared;
            sink.reportAll(r.diagnostics);
            ok = ok && r.ok;
            CatalogStage cst{shader.stages[si].stage, r.stage.text, {}};
            for (const auto& f : r.stage.files) {
                auto shown = shownPaths.find(f.path);
                if (shown == shownPaths.end()) shown = shownPaths.emplace(f.path, embeddedLocation(f.path, o)).first;
                cst.files.push_back(shown->second);
                included.add(f);
            }
            rc.filesRead.insert(rc.filesRead.end(), r.stage.filesRead.begin(), r.stage.filesRead.end());
            cv.stages.push_back(std::move(cst));
            stages.push_back(std::move(r.stage));
        }
        cs.variants.push_back(std::move(cv));
        resolvedVariants.push_back(std::move(stages));
    }
    if (!ok) return false;
    rc.data.shaders.push_back(std::move(cs));
    rc.resolved.push_back(std::move(resolvedVariants));
    rc.stagePaths.push_back(std::move(plan.stagePaths));
    return true;
}

// Phase 5: a "*" filter must name axes that some shader declares, or it is a typo.
void checkWildcardFilters(const std::vector<VariantFilter>& filters, const CatalogData& data, DiagnosticSink& sink) {
    for (const auto& f : filters) {
        if (f.shader != "*") continue;
        for (const auto& [name, value] : f.fixed) {
            bool declared = false;
            for (const auto& cs : data.shaders)
                for (const auto& axis : cs.axes) declared = declared || axis.name == name;
            if (!declared)
                sink.report(makeError(
                    "", 0, 0, "--variant *:" + name + "=" + value + ": no shader declares a variant '" + name + "'"));
        }
    }
}

// Phase 6: the modules (the include dirs' .glsl files plus every other file a stage
// included; those in an -I dir are known already) and each shader's list of them.
void attachModules(const Options& o, const std::vector<ShaderInput>& shaders, const IncludedFiles& included,
                   const SourceReader& reader, ResolvedCatalog& rc, DiagnosticSink& sink) {
    std::vector<std::string> extra;
    std::set<std::string> used;
    for (const auto& [canonical, path] : included.pathOf) {
        extra.push_back(path);
        used.insert(canonical);
    }
    auto modules = indexModules(o, shaders, extra, used, reader, sink);
    for (const auto& m : modules.modules) rc.filesRead.push_back(m.sourcePath);
    for (std::size_t s = 0; s < rc.data.shaders.size(); ++s) {
        std::set<std::uint32_t> shaderModules;
        for (const auto& variant : rc.resolved[s])
            for (const auto& stage : variant)
                for (const auto& f : stage.files)
                    if (auto it = modules.byCanonical.find(f.canonical);
                        f.number > 0 && it != modules.byCanonical.end())
                        shaderModules.insert(it->second);
        rc.data.shaders[s].modules.assign(shaderModules.begin(), shaderModules.end());
    }
    rc.data.modules = std::move(modules.modules);
}

}  // namespace

ResolvedCatalog resolveCatalog(const Options& o, const std::vector<ShaderInput>& shaders, const Contract& contract,
                               const SourceReader& reader) {
    DiagnosticSink sink;
    ResolvedCatalog rc;
    rc.data.nameSpace = o.nameSpace;
    rc.data.contract = contract;
    for (const auto& file : contract.files) rc.data.contractFiles.push_back(embeddedLocation(file, o));
    rc.data.versionDirective = versionDirective(o.glslVersion, o.glslProfile);
    rc.data.rules = o.rules;
    rc.filesRead = contract.files;
    auto filters = parseVariantFilters(o.variantFilters);
    sink.reportAll(filters.diagnostics);

    const auto start = std::chrono::steady_clock::now();
    if (o.printStats)
        if (const auto version = parseVersionDirective(rc.data.versionDirective))
            rc.builtInsMs = buildGlslangBuiltIns(*version);
    const ResolveOptions base{.includeDirs = o.includeDirs,
                              .defines = o.defines,
                              .defaultVersion = rc.data.versionDirective,
                              .baseDir = o.baseDir,
                              .rules = o.rules};
    const auto baseRuns = resolveBaseRuns(o, shaders, base, reader);
    for (const auto& runs : baseRuns) rc.preprocessorRuns += runs.size();
    IncludedFiles included;
    std::vector<ShaderPlan> plans;
    for (std::size_t s = 0; s < shaders.size(); ++s)
        plans.push_back(planShader(shaders[s], baseRuns[s], filters.filters, included));
    resolvePlannedVariants(o, base, plans, baseRuns, reader);
    std::map<std::string, EmbeddedPath> shownPaths;  // every variant names the same few files
    for (std::size_t s = 0; s < shaders.size(); ++s) {
        sink.reportAll(plans[s].diagnostics);
        if (plans[s].ok) assembleShader(o, shaders[s], plans[s], included, shownPaths, rc, sink);
    }
    checkWildcardFilters(filters.filters, rc.data, sink);
    attachModules(o, shaders, included, reader, rc, sink);
    rc.resolveMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    rc.diagnostics = sink.diagnostics();
    return rc;
}

std::string fingerprint(const ResolvedCatalog& rc) {
    // Over the resolved texts, paths and everything else the generated files print.
    hash::ContentHash h;
    const auto mix = [&](std::string_view part) { h.add(part); };
    const auto& d = rc.data;
    mix(PRISM_VERSION);
    mix(format::kLayoutVersion);
    mix(d.nameSpace);
    mix(d.versionDirective);
    for (const auto& f : d.contractFiles) mix(f.path + '\0' + std::to_string(f.searchDir));
    if (d.rules.spirvEnv) mix(spirvEnvName(*d.rules.spirvEnv));  // OpenGL catalogues: as before
    mix(d.sourcesBlock);                                         // so a header with a stale record is rewritten
    for (const auto& s : d.shaders) {
        mix(s.name);
        for (const auto& a : s.axes) {
            mix(a.name);
            for (const auto& v : a.values) mix(v);
        }
        for (const auto& v : s.variants)
            for (const auto& st : v.stages) {
                mix(st.text);
                for (const auto& f : st.files) {
                    mix(f.path);
                    if (f.searchDir) mix("@I" + std::to_string(f.searchDir));  // base-dir paths: as before
                }
            }
        for (auto m : s.modules) mix(std::to_string(m));
    }
    for (const auto& m : d.modules) {
        mix(m.identifier);
        mix(m.path);
        if (m.searchDir) mix("@I" + std::to_string(m.searchDir));
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
    return h.hex64();
}

void fillDataFileRecord(const Options& o, ResolvedCatalog& catalog, const SourceReader& reader) {
    if (o.checkOnly || o.output.empty()) return;
    catalog.data.sourcesBlock = sourcesBlock(recordSources(o, catalog.filesRead, reader));
    catalog.data.fingerprint = fingerprint(catalog);
}

}  // namespace prism::shaderc
