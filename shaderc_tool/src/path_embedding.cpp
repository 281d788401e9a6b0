// embeddedPath(), embeddedLocation(), shownPath(), recordedName(): how file paths appear
// in the generated files (see source_reader.hpp and shown_path.hpp).
#include <filesystem>

#include "shown_path.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

std::string embeddedPath(const std::string& path, const std::string& baseDir) {
    namespace fs = std::filesystem;
    fs::path p(path), base(baseDir);
    if (!p.is_absolute() || !base.is_absolute()) return p.lexically_normal().generic_string();
    auto rel = p.lexically_normal().lexically_relative(base.lexically_normal());
    return rel.empty() ? p.generic_string() : rel.generic_string();
}

namespace {

namespace fs = std::filesystem;

// `path` relative to `dir` when it lies inside it ("." for `dir` itself).
bool inside(const fs::path& path, const std::string& dir, std::string& relative) {
    const auto rel = path.lexically_relative(fs::absolute(dir).lexically_normal());
    if (rel.empty() || *rel.begin() == "..") return false;
    relative = rel.generic_string();
    return true;
}

}  // namespace

EmbeddedPath embeddedLocation(const std::string& path, const Options& o) {
    const auto abs = fs::absolute(path).lexically_normal();
    std::string rel;
    if (inside(abs, o.baseDir, rel)) return {rel, 0};
    for (std::size_t k = 0; k < o.includeDirs.size(); ++k)
        if (inside(abs, o.includeDirs[k], rel)) return {rel, static_cast<std::uint32_t>(k + 1)};
    return {embeddedPath(abs.string(), o.baseDir), 0};
}

std::string shownPath(const std::string& path, const Options& o) {
    return embeddedLocation(path, o).path;
}

std::string recordedName(const std::string& path, const Options& o) {
    const auto abs = fs::absolute(path).lexically_normal();
    std::string rel;
    if (inside(abs, o.baseDir, rel)) return rel;
    for (std::size_t k = 0; k < o.includeDirs.size(); ++k)
        if (inside(abs, o.includeDirs[k], rel)) return "@I" + std::to_string(k) + (rel == "." ? "" : "/" + rel);
    return embeddedPath(abs.string(), o.baseDir);
}

std::string recordedToPath(const std::string& name, const Options& o) {
    if (name.starts_with("@I")) {
        const auto slash = name.find('/');
        const std::string digits = name.substr(2, slash == std::string::npos ? std::string::npos : slash - 2);
        std::size_t k = 0;
        bool number = !digits.empty() && digits.size() < 6;
        for (char c : digits) {
            number = number && c >= '0' && c <= '9';
            k = k * 10 + static_cast<std::size_t>(c - '0');
        }
        if (number && k < o.includeDirs.size()) {
            const auto dir = fs::absolute(o.includeDirs[k]).lexically_normal().string();
            return slash == std::string::npos ? dir : joinPath(dir, name.substr(slash + 1));
        }
    }
    return joinPath(o.baseDir, name);
}

}  // namespace prism::shaderc
