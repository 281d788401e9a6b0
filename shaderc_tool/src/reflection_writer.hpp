// Part of stage 6 (outputs.hpp): the machine-readable reflection of --emit-reflection FILE.json,
// for tools and tests that read a catalogue's layout without compiling C++ (the oracle test
// against `spirv-cross --reflect`, tests/shaderc/test_reflection_oracle.cpp). One JSON object
// per run: {"format", "shaders": [{"name", "variants": [{"name", "defines", "spirv": {stage:
// file name under --emit-spirv's DIR}, "inputs", "resources", "pushConstants",
// "specConstants"}]}]}, the same records the C++ catalogue gets (prism/catalog/shader_catalog.hpp),
// with GLSL type names. Only variants with SPIR-V (the Vulkan client, the spirv target) are
// written. Format: docs/targets.md, "Reflection".
//
//   std::string error;
//   writeIfChanged("build/reflection.json", writeReflectionJson(catalog.data), error);
#pragma once

#include <string>

#include "catalog_model.hpp"

namespace prism::shaderc {

std::string writeReflectionJson(const CatalogData& catalog);

}  // namespace prism::shaderc
