// embeddedPath(): how file paths appear in generated headers (see source_reader.hpp).
#include <filesystem>

#include "source_reader.hpp"

namespace prism::shaderc {

std::string embeddedPath(const std::string& path, const std::string& baseDir) {
    namespace fs = std::filesystem;
    fs::path p(path), base(baseDir);
    if (!p.is_absolute() || !base.is_absolute()) return p.lexically_normal().generic_string();
    auto rel = p.lexically_normal().lexically_relative(base.lexically_normal());
    return rel.empty() ? p.generic_string() : rel.generic_string();
}

}  // namespace prism::shaderc
