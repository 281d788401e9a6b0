// Part of stage 6 (header_writer.hpp): the C++ structs of a Vulkan-client catalogue's blocks.
// For each uniform block, storage block (its fixed part: a runtime array is left out) and
// push-constant block, the generated header declares, in `<namespace>::blocks::<shader>`, a
// standard-layout struct named as the block's type whose members lie at the offsets the
// SPIR-V declares, with static_asserts on offsetof and sizeof, so a layout that drifts from
// the shader is a compile error (after sokol-shdc's `<name>_t`). glm types where they fit
// (vec3 at its offset, mat4, mat3 with 16-byte columns as glm::mat3x4), an element padded to
// its array stride as prism::catalog::Padded<T, Stride> (prism/catalog/block_struct.hpp),
// explicit `std::byte` padding between members, a buffer_reference member as std::uint64_t.
// Variants usually share a layout: a block whose layout every variant agrees on is declared
// once; one whose layout differs is declared per variant in `<shader>::<variant>` (the
// variant's defines as an identifier, e.g. `FOG_1`).
//
//   std::ostringstream out;
//   writeBlockStructs(out, catalog);   // inside the catalogue's namespace
#pragma once

#include <ostream>

#include "catalog_model.hpp"

namespace prism::shaderc {

// Nothing for an OpenGL-client catalogue.
void writeBlockStructs(std::ostream& out, const CatalogData& catalog);

}  // namespace prism::shaderc
