// The validation cache's directory and the --stats line (see validation_settings.hpp).
#include "validation_settings.hpp"

#include <filesystem>
#include <iomanip>
#include <ostream>

#include "output_options.hpp"
#include "prism/hash/content_hash.hpp"

namespace prism::shaderc {

std::string catalogueCacheKey(const Options& o) {
    hash::ContentHash h;
    h.add("catalogue");
    for (const auto& line : outputOptionLines(o, kValidationPack)) h.add(line);
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
