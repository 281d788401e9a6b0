// Part of stage 1: the text of a --program argument, NAME=FILE[,FILE...], split without
// reading a file (program_declarations.hpp reads and checks the files in stage 3; the run
// record, output_options.hpp, writes the declaration with its paths made relative).
//
//   splitProgramFiles("a.vert,b.frag")                      -> {"a.vert", "b.frag"}
//   declarationWithPaths("lit=/w/a.vert,/w/b.frag", relative) -> "lit=a.vert,b.frag"
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace prism::shaderc {

// The comma-separated file list of a declaration (empty entries kept, for their error).
std::vector<std::string> splitProgramFiles(const std::string& list);

// The declaration with each file written as `pathOf` gives it (the records of an unchanged
// run use paths relative to --base-dir, so they stay free of the checkout's place).
std::string declarationWithPaths(const std::string& declaration,
                                 const std::function<std::string(const std::string&)>& pathOf);

}  // namespace prism::shaderc
