// prism-shaderc's whole command line as a function: the executable is a thin client of the
// library (shaderc_tool/main.cpp), and a program may run the build step in process.
//
// Usage (snippet: examples/snippets/shaderc_tool.cpp):
//
//     #include "prism/shaderc/tool.hpp"
//     char name[] = "prism-shaderc", flag[] = "--version";
//     char* argv[] = {name, flag};
//     int status = prism::shaderc::runTool(2, argv);  // prints "prism-shaderc <version>"; 0
#pragma once

namespace prism::shaderc {

// Exit status: 0 success, 1 shader errors, 2 usage or I/O errors; messages go to stderr.
int runTool(int argc, char** argv);

}  // namespace prism::shaderc
