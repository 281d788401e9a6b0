// Writing outputs atomically and only when their content changes: a no-op rebuild
// touches nothing, and an interrupted run never leaves a half-written file.
#pragma once

#include <string>

namespace prism::shaderc {

enum class WriteOutcome { Unchanged, Written, Failed };

// Writes `content` to a temporary file beside `path` and renames it over `path`,
// unless `path` already holds exactly `content`. Creates missing parent directories.
// On failure `error` says why.
WriteOutcome writeIfChanged(const std::string& path, const std::string& content, std::string& error);

// Sets the modification time of `path` to now, creating it empty if needed.
bool touchFile(const std::string& path, std::string& error);

}  // namespace prism::shaderc
