// What glslang's tokens can depend on in a GLSL file, for the clean-check shortcut
// (up_to_date.hpp, a --check without emitted files): the text with comments removed, runs of blanks collapsed to one
// space, line ends trimmed and blank lines dropped. Two texts with the same signature
// give the same token stream, except where __LINE__ is used (line numbers shift): such
// a file's signature is its whole text. Conservative by construction: whatever might be
// code stays in the signature (a quoted "//" is kept; a comment continued by a trailing
// backslash keeps its next line).
//
//   codeSignature("vec3 a; // note\n\n  float  b;") == "vec3 a;\nfloat b;\n"
#pragma once

#include <string>
#include <string_view>

namespace prism::shaderc {

std::string codeSignature(std::string_view text);

// .glsl, .vert, .geom, .frag and .comp files get a code signature; others (contract JSON)
// are compared by their whole text.
bool hasCodeSignature(std::string_view path);

}  // namespace prism::shaderc
