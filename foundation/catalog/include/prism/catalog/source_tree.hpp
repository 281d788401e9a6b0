// Where a catalogue's sources lie on the machine that built it: what hot reload
// (prism/render/shader_watcher.hpp) needs to rebuild the catalogue's programs as
// prism-shaderc did. prism_add_shaders(<target> HEADER x.hpp) writes it, as
// `<namespace>::kSourceTree`, into x_sources.hpp beside the catalogue's header: apart from
// the catalogue, whose generated files name no absolute path and are byte-identical
// wherever the checkout lies. The catalogue's own line tables say which of these folders
// each path is relative to (catalog::SourceFile::searchDir).
//
// Usage (snippet: examples/snippets/catalog_source_tree.cpp):
//
//     #include "prism/shaders_sources.hpp"  // generated beside prism/shaders.hpp
//     const prism::catalog::SourceTree& tree = prism::shaders::kSourceTree;
//     std::cout << tree.nameSpace << " was built from " << tree.baseDir << " with -I " << tree.moduleDirs[0]
//               << "\n";  // prism::shaders was built from /src/prism with -I /src/prism/modules
#pragma once

#include <span>
#include <string_view>

#include "prism/catalog/shader_catalog.hpp"

namespace prism::catalog {

// prism-shaderc's command line for one catalogue, as absolute paths.
struct SourceTree {
    std::string_view nameSpace;                       // the catalogue's namespace, e.g. "prism::shaders"
    std::string_view baseDir;                         // --base-dir: searchDir 0
    std::span<const std::string_view> moduleDirs;     // -I, in order: searchDir k is moduleDirs[k - 1]
    std::span<const std::string_view> contractFiles;  // --contract; none: Prism's built-in contract
    std::span<const Define> defines;                  // -D NAME[=VALUE] (VALUE "1" when left out)
};

}  // namespace prism::catalog
