// The usage example of prism/catalog/source_tree.hpp, compiled and run by tests/snippets.
#include <iostream>
#include <string>

// [snippet]
#include "prism/shaders_sources.hpp"  // generated beside prism/shaders.hpp
// [/snippet]

int main() {
    // [snippet]
    const prism::catalog::SourceTree& tree = prism::shaders::kSourceTree;
    std::cout << tree.nameSpace << " was built from " << tree.baseDir << " with -I " << tree.moduleDirs[0]
              << "\n";  // prism::shaders was built from /src/prism with -I /src/prism/modules
    // [/snippet]
    const std::string expected = std::string(tree.baseDir) + "/modules";
    return tree.nameSpace == "prism::shaders" && tree.moduleDirs.size() == 1 && tree.moduleDirs[0] == expected &&
                   tree.contractFiles.size() == 1
               ? 0
               : 1;
}
