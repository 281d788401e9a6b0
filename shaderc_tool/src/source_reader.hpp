// File access for the include resolver, injectable so tests run on in-memory files
// (the idea of Filament's include callback). DiskReader reads the real file system;
// MemoryReader serves a map of path -> text.
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace prism::shaderc {

class SourceReader {
  public:
    virtual ~SourceReader() = default;
    // A canonical key for `path` if the file exists (symlinks and ./.. resolved), else nullopt.
    virtual std::optional<std::string> canonical(const std::string& path) const = 0;
    // The text of an existing file, or nullopt when it cannot be read.
    virtual std::optional<std::string> read(const std::string& path) const = 0;
};

// Reads each file and resolves each path once per run: a catalogue's stages include
// the same modules again and again (thread-safe).
class DiskReader final : public SourceReader {
  public:
    std::optional<std::string> canonical(const std::string& path) const override;
    std::optional<std::string> read(const std::string& path) const override;

  private:
    mutable std::mutex mutex_;
    mutable std::map<std::string, std::optional<std::string>> canonicalCache_;
    mutable std::map<std::string, std::optional<std::string>> textCache_;
};

// Paths are normalised lexically ("a/./b/../c" == "a/c"); no symlinks.
class MemoryReader final : public SourceReader {
  public:
    MemoryReader() = default;
    MemoryReader(std::initializer_list<std::pair<const std::string, std::string>> files);
    void add(const std::string& path, std::string text);
    std::optional<std::string> canonical(const std::string& path) const override;
    std::optional<std::string> read(const std::string& path) const override;

  private:
    std::map<std::string, std::string> files_;
};

// Joins and normalises lexically ("dir/" + "../x.glsl"); used by both readers.
std::string joinPath(const std::string& dir, const std::string& file);
std::string parentDir(const std::string& path);

}  // namespace prism::shaderc

namespace prism::shaderc {
// The path as embedded in generated code: relative to `baseDir` when both are
// absolute (so headers do not depend on where the checkout lives), else normalised.
std::string embeddedPath(const std::string& path, const std::string& baseDir);
}  // namespace prism::shaderc
