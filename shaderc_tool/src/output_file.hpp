// Writing outputs atomically and only when their content changes: a no-op rebuild
// touches nothing, and an interrupted run never leaves a half-written file.
#pragma once

#include <filesystem>
#include <string>

namespace prism::shaderc {

enum class WriteOutcome { Unchanged, Written, Failed };

// Writes `content` to a temporary file beside `path` and renames it over `path`,
// unless `path` already holds exactly `content`. Creates missing parent directories.
// On failure `error` says why. Temp files of earlier runs that were killed mid-write
// (`<path>.tmp.<pid>` of a process that no longer exists) are removed first.
WriteOutcome writeIfChanged(const std::string& path, const std::string& content, std::string& error);

// Removes `<path>.tmp.<pid>` files that runs killed mid-write left behind (their
// process no longer exists); a live writer's temp file is kept.
void removeStaleTemps(const std::filesystem::path& path);

// Sets the modification time of `path` to now, creating it empty if needed.
bool touchFile(const std::string& path, std::string& error);

}  // namespace prism::shaderc
