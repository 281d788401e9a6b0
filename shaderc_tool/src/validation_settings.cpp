// The validation cache's directory and the --stats line (see validation_settings.hpp).
#include "validation_settings.hpp"

#include <filesystem>
#include <ostream>

namespace prism::shaderc {

std::string validationCacheDir(const Options& o) {
    if (o.cacheDir == "none") return {};
    if (!o.cacheDir.empty()) return o.cacheDir;
    if (o.stamp.empty()) return {};
    const auto parent = std::filesystem::path(o.stamp).parent_path();
    return (parent.empty() ? std::filesystem::path("prism-shaderc-cache") : parent / "prism-shaderc-cache").string();
}

void printValidationStats(std::ostream& out, const ValidationStats& s) {
    out << "prism-shaderc: validated " << s.validated << " of " << s.programs << " programs ("
        << s.programs - s.distinct << " shared a token stream, " << s.fromCache << " from the cache; "
        << s.stagesCompiled << " stages parsed)\n";
}

}  // namespace prism::shaderc
