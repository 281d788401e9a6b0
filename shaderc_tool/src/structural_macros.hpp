// Which macros can change what a resolution run decides (variant_resolution.hpp): the
// files glslang enters, in which order, and the #version / #pragma / #extension / #error
// / #line lines it reaches. A macro that appears only in ordinary code, or only in
// conditions whose groups hold nothing but code, changes the token stream but not the
// flattened text, so variants that differ only in such macros share one run.
//
// The set is found lexically, and is closed: a decisive directive (anything but
// #if/#ifdef/#ifndef/#elif/#else/#endif/#define/#undef, and a lone '#') makes the
// identifiers in the conditions of every group around it (all branches' conditions)
// structural, and those of its own line unless glslang never expands them (#pragma,
// #extension, #version, #error, and a "quoted" or <angled> #include name); a #define
// or #undef of a structural macro makes the identifiers of its line and of the
// conditions around it structural. So in two runs
// whose macros agree on the structural names, every decisive directive is reached or
// skipped alike and every structural macro has the same value wherever it is read.
//
//   auto found = structuralMacros({"#if FOG\n#include <fog.glsl>\n#endif\nfloat f = BLINN;\n"});
//   // found->decisive == {"FOG"} (BLINN is only in code); found->defined is empty
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace prism::shaderc {

struct StructuralMacros {
    std::set<std::string> decisive;  // names whose values can change the run's decisions
    std::set<std::string> defined;   // every name a #define of the texts defines
};

// nullopt when it cannot be told lexically: a text pastes tokens (`##` can build any
// name) or a file's conditional groups do not balance.
std::optional<StructuralMacros> structuralMacros(const std::vector<std::string_view>& texts);

}  // namespace prism::shaderc
