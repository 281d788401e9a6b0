// Make-syntax depfile of every file a run read, for add_custom_command(DEPFILE).
// Escapes as GNU Make and Ninja expect: space -> `\ `, `$` -> `$$`, `#` -> `\#`.
#pragma once

#include <string>
#include <vector>

namespace prism::shaderc {

std::string escapeDepfilePath(const std::string& path);

// `target: dep1 dep2 ...` with one dependency per continued line, deduplicated, sorted.
std::string makeDepfile(const std::string& target, std::vector<std::string> dependencies);

}  // namespace prism::shaderc
