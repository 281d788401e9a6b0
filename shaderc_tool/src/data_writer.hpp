// Part of stage 6 (outputs.hpp): the data file X.cpp beside the header X.hpp
// (header_writer.hpp). Each distinct piece of GLSL text is stored once, in a pool of raw
// string literals; a stage is a list of references to pool pieces, and so is a module's
// own text. The file ends with the records the no-op check reads back (up_to_date.hpp):
// the inputs fingerprint in its banner, the header's hash, and the sources record. Tags
// and layout: generated_format.hpp.
//
//   const std::string header = writeHeader(catalog, "shaders.cpp");
//   writeIfChanged(dataPathFor("gen/shaders.hpp"), writeData(catalog, "shaders.hpp", header), error);
#pragma once

#include <string>

#include "catalog_model.hpp"
#include "data_file_records.hpp"

namespace prism::shaderc {

// The data file's text; it includes the header by its file name (it sits beside it) and
// records a hash of `headerText`, so that a run can tell a stale or edited header.
std::string writeData(const CatalogData& catalog, const std::string& headerFileName, const std::string& headerText);

}  // namespace prism::shaderc
