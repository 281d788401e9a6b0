// Part of stage 6 (outputs.hpp): prints the catalogue as C++, split in two files so that a
// module edit recompiles one translation unit:
//   - the header (-o X.hpp): a banner, `enum class ShaderId`, `enum class ModuleId`, the
//     names and module paths as constexpr tables, and declarations of the data
//     (`extern const prism::catalog::Catalog kCatalog;`, shaderInfo(), moduleInfo()).
//     It changes only when a shader or module is added, removed or renamed, or a
//     shader's uniforms change (the typed handles, prism/catalog/uniform_handle.hpp).
//   - the data file (X.cpp, data_writer.hpp): every module text and stage body once, each
//     stage as a list of references to them, line tables, reflection, the contract and
//     the no-op record. A text edit changes only this file.
// Both texts are pure functions of the catalogue: byte-identical across runs and checkouts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "catalog_model.hpp"

namespace prism::shaderc {

inline constexpr std::size_t kMaxChunkBytes = 16000;

// The header's text. It names the data file in a comment only (by file name).
std::string writeHeader(const CatalogData& catalog, const std::string& dataFileName);

// Splits at line ends so that no chunk exceeds `maxBytes` (a longer line is cut).
std::vector<std::string> splitIntoChunks(const std::string& text, std::size_t maxBytes = kMaxChunkBytes);

// A raw string literal for `text` with a delimiter that does not occur in it.
std::string rawStringLiteral(const std::string& text);

// `s` as an ordinary C++ string literal (quotes and backslashes escaped).
std::string quotedLiteral(const std::string& s);

// `v` as a 0x%04X literal (GL type enums).
std::string hexLiteral(std::uint32_t v);

}  // namespace prism::shaderc
