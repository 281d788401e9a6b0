// The clean-check shortcut of --check (see clean_check.hpp).
#include "clean_check.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "output_file.hpp"
#include "source_fingerprint.hpp"
#include "validation_settings.hpp"

namespace prism::shaderc {
namespace {

std::string recordPath(const Options& o) {
    const std::string dir = validationCacheDir(o);
    if (!o.checkOnly || !o.emitGlslDir.empty() || !o.emitSpirvDir.empty() || !o.emitWeb.empty() ||
        !o.emitReflection.empty() || dir.empty())
        return {};
    return (std::filesystem::path(dir) / (catalogueCacheKey(o) + ".clean-check")).string();
}

}  // namespace

std::optional<std::vector<std::string>> unchangedSinceCleanCheck(const Options& o, const SourceReader& reader) {
    const std::string path = recordPath(o);
    if (path.empty() || o.revalidate) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return unchangedSources(o, text.str(), reader, ContentKey::Code);
}

bool recordCleanCheck(const Options& o, const std::vector<std::string>& filesRead, const SourceReader& reader) {
    const std::string path = recordPath(o);
    if (path.empty()) return true;
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    std::string error;
    const std::string record = sourcesBlock(recordSources(o, filesRead, reader, ContentKey::Code));
    if (writeIfChanged(path, record, error) == WriteOutcome::Failed) {
        std::cerr << "prism-shaderc: warning: the clean-check record was not written: " << error << "\n";
        return false;
    }
    return true;
}

void forgetCleanCheck(const Options& o) {
    const std::string path = recordPath(o);
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove(path, ec);
}

}  // namespace prism::shaderc
