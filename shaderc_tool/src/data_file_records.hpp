// What a generated data file records, read by whichever stage needs it (the no-op check of
// stage 2, the header and data writers of stage 6, the option checks of stage 1): where the
// data file of a header lies, the hash of its header, the inputs fingerprint in its banner.
// The layout of both files is generated_format.hpp's.
//
//   const auto data = readWholeFile(dataPathFor("gen/shaders.hpp"));  // gen/shaders.cpp
//   if (headerMatchesData(readWholeFile("gen/shaders.hpp"), data) && recordedFingerprint(data) == fingerprint) ...
#pragma once

#include <string>

namespace prism::shaderc {

// Where the data file of header `headerPath` goes: the same path with extension .cpp.
std::string dataPathFor(const std::string& headerPath);

// The hash of a header's text, as the data file records it after format::kHeaderHashLine.
std::string headerHash(const std::string& headerText);

// True when `dataText` (or its tail) records the hash of `headerText`.
bool headerMatchesData(const std::string& headerText, const std::string& dataText);

// The fingerprint recorded in an existing data file's banner, or "" when there is none.
std::string recordedFingerprint(const std::string& dataText);

}  // namespace prism::shaderc
