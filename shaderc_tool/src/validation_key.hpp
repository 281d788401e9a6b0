// The key under which a flattened stage is validated once and its result cached
// (validation_scheduler.hpp, validation_cache.hpp): two stages with the same key are the
// same token stream for the compiler, so glslang accepts or rejects both alike.
//
// The key hashes the #version line, the variant's defines whose names appear in the code
// of some file the stage read (a macro met nowhere, or only in comments and in #pragma,
// #extension, #version or #error lines, which glslang never expands, changes no token), and the code signature
// (code_signature.hpp) of the flattened text below the define block with its `#line`
// markers left out: comments, blanks and line layout change no token. A text that
// uses __LINE__ or __FILE__ (whose values the markers set) is hashed whole, and so are
// the defines when a file pastes tokens (`##` can build any macro's name).
//
//   stage.validationKey = validationKey(stage, options.defines, reader);
//   // or, for many variants sharing one run's files and body:
//   const auto basis = validationKeyBasis(run.stage, run.defineCount, names, reader);
//   stage.validationKey = validationKey(stage, options.defines, basis);
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "include_resolver.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

using DefineList = std::vector<std::pair<std::string, std::string>>;

// What a key needs from the files a run read and from its text below the define block
// (`defineCount` #define lines): the same for every variant sharing that run.
struct ValidationKeyBasis {
    std::string body;              // hash of the body's signature
    std::vector<std::string> met;  // those of `names` that the files meet (all when a file pastes tokens)
};
ValidationKeyBasis validationKeyBasis(const ResolvedStage& stage, std::size_t defineCount,
                                      const std::vector<std::string>& names, const SourceReader& reader);

std::string validationKey(const ResolvedStage& stage, const DefineList& defines, const ValidationKeyBasis& basis);
std::string validationKey(const ResolvedStage& stage, const DefineList& defines, const SourceReader& reader);

}  // namespace prism::shaderc
