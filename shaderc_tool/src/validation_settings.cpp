// The validation cache's directory and the --stats line (see validation_settings.hpp).
#include "validation_settings.hpp"

#include <filesystem>
#include <iomanip>
#include <ostream>

#include "prism/hash/content_hash.hpp"

namespace prism::shaderc {

std::string validationCacheDir(const Options& o) {
    if (o.cacheDir == "none") return {};
    if (!o.cacheDir.empty()) return o.cacheDir;
    if (o.stamp.empty()) return {};
    const auto parent = std::filesystem::path(o.stamp).parent_path();
    return (parent.empty() ? std::filesystem::path("prism-shaderc-cache") : parent / "prism-shaderc-cache").string();
}

std::string catalogueCacheKey(const Options& o) {
    hash::ContentHash h;
    h.add("catalogue");
    for (const auto& list : {o.inputs, o.includeDirs, o.contracts, o.variantFilters}) {
        h.add(std::to_string(list.size()));
        for (const auto& item : list) h.add(item);
    }
    for (const auto& [name, value] : o.defines) h.add(name).add(value);
    for (const auto& declaration : o.programs) h.add("--program").add(declaration);
    h.add(std::to_string(o.glslVersion)).add(o.glslProfile).add(o.baseDir);
    if (o.warnUndocumentedLibraryModules) h.add("warn-undocumented-modules=all");  // more warnings, another record
    if (o.rules.spirvEnv) h.add(spirvEnvName(*o.rules.spirvEnv));
    if (o.targets != std::vector<Target>{Target::Gl}) h.add("--target " + targetListText(o.targets));
    return h.hex();
}

void printResolutionStats(std::ostream& out, const ResolvedCatalog& catalog) {
    std::size_t stages = 0, shared = 0;
    for (const auto& shader : catalog.resolved)
        for (const auto& variant : shader)
            for (const auto& stage : variant) {
                ++stages;
                shared += stage.shared;
            }
    out << "prism-shaderc: resolved " << stages << " stages with " << catalog.preprocessorRuns
        << " runs of glslang's preprocessor (" << shared << " shared another run) in " << std::fixed
        << std::setprecision(1) << catalog.resolveMs << " ms, " << catalog.builtInsMs
        << " ms of it glslang's built-in tables\n";
}

void printValidationStats(std::ostream& out, const ValidationStats& s) {
    out << "prism-shaderc: validated " << s.validated << " of " << s.programs << " programs ("
        << s.programs - s.distinct << " shared a token stream, " << s.fromCache << " from the cache; "
        << s.stagesCompiled << " stages parsed) in " << std::fixed << std::setprecision(1) << s.ms << " ms\n";
}

}  // namespace prism::shaderc
