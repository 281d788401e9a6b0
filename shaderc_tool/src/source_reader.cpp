// File access for the include resolver: the real file system (DiskReader), an
// in-memory map for tests (MemoryReader), and the lexical path helpers both use.
#include "source_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;

// Forward slashes, no "." or ".." left where they can be folded, no trailing slash.
std::string normalisedGeneric(const fs::path& path) {
    std::string text = path.lexically_normal().generic_string();
    while (text.size() > 1 && text.back() == '/') text.pop_back();
    return text;
}

std::string withForwardSlashes(std::string text) {
    std::replace(text.begin(), text.end(), '\\', '/');
    return text;
}

}  // namespace

std::string joinPath(const std::string& dir, const std::string& file) {
    const fs::path filePath(withForwardSlashes(file));
    if (dir.empty() || filePath.is_absolute()) return normalisedGeneric(filePath);
    return normalisedGeneric(fs::path(withForwardSlashes(dir)) / filePath);
}

std::string parentDir(const std::string& path) {
    const std::string normalised = joinPath("", path);
    return fs::path(normalised).parent_path().generic_string();
}

std::optional<std::string> DiskReader::canonical(const std::string& path) const {
    std::lock_guard lock(mutex_);
    if (auto it = canonicalCache_.find(path); it != canonicalCache_.end()) return it->second;
    std::optional<std::string> result;
    std::error_code error;
    if (fs::is_regular_file(path, error)) {
        const fs::path resolved = fs::canonical(path, error);
        if (!error) result = resolved.generic_string();
    }
    canonicalCache_.emplace(path, result);
    return result;
}

std::optional<std::string> DiskReader::read(const std::string& path) const {
    std::lock_guard lock(mutex_);
    if (auto it = textCache_.find(path); it != textCache_.end()) return it->second;
    std::optional<std::string> result;
    std::ifstream in(path, std::ios::binary);
    if (in) {
        std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (!in.bad()) result = std::move(text);
    }
    textCache_.emplace(path, result);
    return result;
}

MemoryReader::MemoryReader(std::initializer_list<std::pair<const std::string, std::string>> files) {
    for (const auto& [path, text] : files) add(path, text);
}

void MemoryReader::add(const std::string& path, std::string text) {
    files_[joinPath("", path)] = std::move(text);
}

std::optional<std::string> MemoryReader::canonical(const std::string& path) const {
    std::string key = joinPath("", path);
    if (!files_.contains(key)) return std::nullopt;
    return key;
}

std::optional<std::string> MemoryReader::read(const std::string& path) const {
    const auto found = files_.find(joinPath("", path));
    if (found == files_.end()) return std::nullopt;
    return found->second;
}

}  // namespace prism::shaderc
