// The usage example of prism/shaderc/tool.hpp, compiled and run by tests/snippets.

// [snippet]
#include "prism/shaderc/tool.hpp"
// [/snippet]

int main() {
    // [snippet]
    char name[] = "prism-shaderc", flag[] = "--version";
    char* argv[] = {name, flag};
    int status = prism::shaderc::runTool(2, argv);  // prints "prism-shaderc <version>"; 0
    // [/snippet]
    return status;
}
