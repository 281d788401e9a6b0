// "Did you mean" hints for prism-shaderc's diagnostics: the closest known name by edit
// distance (the rule itself is public, prism/catalog/did_you_mean.hpp, shared with the
// runtime) and the functions a resolved stage defines (for glslang's "no matching
// overloaded function found"). The files an #include could have meant are include_search.cpp's.
//
//   didYouMean("lightng", {"lighting", "fog"})  // " (did you mean 'lighting'?)"
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "prism/catalog/did_you_mean.hpp"

namespace prism::shaderc {

using catalog::closestName;
using catalog::didYouMean;
using catalog::editDistance;

// Names of the functions defined or declared at global scope in GLSL text (a return
// type, a name and a parameter list at the start of a line, outside comments).
std::vector<std::string> functionNamesIn(std::string_view glsl);

}  // namespace prism::shaderc
