// libFuzzer harness: OBJ import (Prism's line-by-line validation, then tinyobjloader)
// into a Mesh, split and welded. The first byte picks the options; the rest is the
// file, served from memory. Oracle: every bad file is an ObjLoadError, no crash, leak
// or undefined behaviour; a loaded mesh has whole triangles with in-range indices.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "prism/geometry/obj_loader.hpp"

using namespace prism::geometry;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    ObjLoadOptions options;
    options.weld = (data[0] & 1) != 0;
    options.useFileNormals = (data[0] & 2) != 0;
    if (data[0] & 4) options.creaseAngleDegrees = static_cast<float>(data[0] >> 3) * 6.0f;
    const prism::fuzz::MemoryFile file(data + 1, size - 1);
    Mesh mesh;
    try {
        mesh = loadObj(file.path(), options);
    } catch (const ObjLoadError&) {
        return 0;
    }
    if (mesh.indices.size() % 3 != 0) std::abort();
    for (auto i : mesh.indices)
        if (i >= mesh.positions.size()) {
            std::fprintf(stderr, "index %u past %zu vertices\n", static_cast<unsigned>(i), mesh.positions.size());
            std::abort();
        }
    return 0;
}
