// Stage 5 of prism-shaderc: prints the catalogue as C++, split in two files so that a
// module edit recompiles one translation unit:
//   - the header (-o X.hpp): a banner, `enum class ShaderId`, `enum class ModuleId`, the
//     names and module paths as constexpr tables, and declarations of the data
//     (`extern const prism::catalog::Catalog kCatalog;`, shaderInfo(), moduleInfo()).
//     It changes only when a shader or module is added, removed or renamed.
//   - the data file (X.cpp, data_writer.cpp): every module text and stage body once, each
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

// The data file's text; it includes the header by its file name (it sits beside it) and
// records a hash of `headerText`, so that a run can tell a stale or edited header.
std::string writeData(const CatalogData& catalog, const std::string& headerFileName, const std::string& headerText);

// True when `dataText` (or its tail) records the hash of `headerText`.
bool headerMatchesData(const std::string& headerText, const std::string& dataText);

// Where the data file of header `headerPath` goes: the same path with extension .cpp.
std::string dataPathFor(const std::string& headerPath);

// The fingerprint recorded in an existing data file's banner, or "" when there is none.
std::string recordedFingerprint(const std::string& dataText);

// Splits at line ends so that no chunk exceeds `maxBytes` (a longer line is cut).
std::vector<std::string> splitIntoChunks(const std::string& text, std::size_t maxBytes = kMaxChunkBytes);

// A raw string literal for `text` with a delimiter that does not occur in it.
std::string rawStringLiteral(const std::string& text);

// `s` as an ordinary C++ string literal (quotes and backslashes escaped).
std::string quotedLiteral(const std::string& s);

// `v` as a 0x%04X literal (GL type enums).
std::string hexLiteral(std::uint32_t v);

// `name` made a valid C++ identifier that is no keyword.
std::string cppIdentifier(const std::string& name);

}  // namespace prism::shaderc
