// libFuzzer harness: PNG height maps and permeability maps of the water system
// (prism::water::loadHeightMap / loadPermeabilityMap through Prism's libpng reader),
// served from memory. Oracle: every bad file is a HeightMapError, no crash, leak,
// undefined behaviour or out-of-memory; a loaded field validates.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "prism/water/height_field.hpp"

using namespace prism::water;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const prism::fuzz::MemoryFile file(data, size);
    HeightField field;
    try {
        field = loadHeightMap(file.path());
    } catch (const HeightMapError&) {
        return 0;
    }
    validate(field, "fuzzed height map");  // throws (and so fails) if the loader accepted a bad field
    try {
        const auto k = loadPermeabilityMap(file.path(), field.width, field.height, 1e-5);
        if (k.size() != field.cellCount()) std::abort();
    } catch (const HeightMapError&) {
        std::fprintf(stderr, "a file that loads as a height map fails as a permeability map of its own size\n");
        std::abort();
    }
    return 0;
}
