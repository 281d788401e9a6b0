// Stage 5 of prism-shaderc: prints the catalogue as a C++ header: a banner, `enum class
// ShaderId`, `enum class ModuleId`, every stage's include-resolved GLSL as raw string
// chunks under 16 KB (MSVC's limit), line tables, reflection tables and constexpr
// lookups. The text is a pure function of the catalogue: byte-identical across runs.
#pragma once

#include <string>
#include <vector>

#include "catalog_model.hpp"

namespace prism::shaderc {

inline constexpr std::size_t kMaxChunkBytes = 16000;

std::string writeHeader(const CatalogData& catalog);

// The fingerprint recorded in an existing header's banner, or "" when there is none.
std::string fingerprintOfHeader(const std::string& headerText);

// Splits at line ends so that no chunk exceeds `maxBytes` (a longer line is cut).
std::vector<std::string> splitIntoChunks(const std::string& text, std::size_t maxBytes = kMaxChunkBytes);

// A raw string literal for `text` with a delimiter that does not occur in it.
std::string rawStringLiteral(const std::string& text);

// `name` made a valid C++ identifier that is no keyword.
std::string cppIdentifier(const std::string& name);

}  // namespace prism::shaderc
