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

// Makes `path` hold `content` with the modification time now, whether or not it held it
// before (a build system's stamp must be newer than the inputs that made it run).
bool touchFile(const std::string& path, const std::string& content, std::string& error);

}  // namespace prism::shaderc
