// How file paths appear in the generated files and in their no-op record: never absolute
// and never dependent on where the checkout or an installed module directory lies.
//
//   shownPath("/w/proj/shaders/a.vert", o)        -> "shaders/a.vert"   (inside --base-dir)
//   shownPath("/opt/prism/modules/lights.glsl", o) -> "lights.glsl"     (under -I /opt/prism/modules)
#pragma once

#include <cstdint>
#include <string>

#include "args.hpp"

namespace prism::shaderc {

// A path as the catalogue embeds it: `path` relative to --base-dir (searchDir 0) or to
// the searchDir-th -I directory, counting from 1 (catalog::SourceFile::searchDir).
struct EmbeddedPath {
    std::string path;
    std::uint32_t searchDir = 0;
};

// shownPath() with the directory it is relative to.
EmbeddedPath embeddedLocation(const std::string& path, const Options& options);

// Relative to --base-dir when `path` lies inside it, else relative to the first -I
// directory that contains it, else relative to --base-dir (with "..").
std::string shownPath(const std::string& path, const Options& options);

// The no-op record's name for `path`: relative to --base-dir when inside it, else
// "@I<k>/<path under the k-th -I directory>"; recordedToPath() reverses it.
std::string recordedName(const std::string& path, const Options& options);
std::string recordedToPath(const std::string& name, const Options& options);

}  // namespace prism::shaderc
