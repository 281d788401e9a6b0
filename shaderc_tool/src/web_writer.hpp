// Part of stage 6 (outputs.hpp): the web catalogue of --emit-web FILE.js, for a WebGL2 page.
// One plain script (no `import`/`export`, so a page opened from file:// loads it with
// <script src>) that adds the catalogue to one global object, PrismWebCatalogs, under the
// catalogue's name (its --namespace, else the file's stem). The entry holds each distinct
// es300 stage text once, and per program its variant axes, the variants that exist (their
// defines, stage texts by index, the #line table's files) with the attributes and uniforms a
// page binds by name, and the module IDs it includes. Shaders the run leaves out of es300
// (`#pragma prism targets gl spirv`) are not in it. The text is deterministic and holds no
// absolute path. Format: docs/targets.md, "Web catalogue"; names: generated_format.hpp.
//
//   std::string error;
//   writeIfChanged("web/shaders.js", writeWebCatalogue(catalog.data, "shaders"), error);
//   // in the page: PrismWebCatalogs["prism::shaders"].programs.phong.variants[0].stages.frag
#pragma once

#include <string>

#include "catalog_model.hpp"

namespace prism::shaderc {

// The catalogue's name in PrismWebCatalogs: its namespace, or `fallback` when it has none
// (a run without -o).
std::string webCatalogueName(const CatalogData& catalog, const std::string& fallback);

// The script's text. Only variants with an es300 text (CatalogVariant::es300) are written.
std::string writeWebCatalogue(const CatalogData& catalog, const std::string& fallbackName);

}  // namespace prism::shaderc
