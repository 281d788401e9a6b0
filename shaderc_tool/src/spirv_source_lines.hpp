// A stage's SPIR-V with OpLine instructions whose file is the stage's source number, so a
// validator message inside a function maps to the module's own file:line. glslang names an
// OpLine's file after a node's `#line N "file"` name only; a flattened stage's `#line N S`
// leaves S in the node's source-string number, which its OpLines would drop. Used only when
// the validator rejected a module: the stored words stay what glslc -g0 writes.
//
//   std::vector<std::uint32_t> words;
//   if (generateSpirvWithSourceNumbers(program, EShLangFragment, words, log)) ...;  // OpLine files "0", "1", ...
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <cstdint>
#include <string>
#include <vector>

namespace prism::shaderc {

// generateSpirv with line info, each OpLine's file the decimal source number of its node.
// The stage's tree is renamed for the call and restored before it returns.
bool generateSpirvWithSourceNumbers(glslang::TProgram& program, EShLanguage stage, std::vector<std::uint32_t>& words,
                                    std::string& log);

}  // namespace prism::shaderc
