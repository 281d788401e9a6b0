// The usage example of prism/water/height_field.hpp, compiled and run by tests/snippets.
// It writes the two grey PNGs the example loads (terrain.png, soil.png) first.
#include "prism/water/rain_rates.hpp"
// [snippet]
#include "prism/water/height_field.hpp"
using namespace prism::water;
// [/snippet]

int main() {
    GreyImage grey{.width = 32, .height = 16, .bitDepth = 16, .values = std::vector<std::uint16_t>(32 * 16, 30000)};
    writeGreyPng("terrain.png", grey);
    writeGreyPng("soil.png", grey);
    // [snippet]
    HeightField t = loadHeightMap("terrain.png", {.cellSize = 0.25f, .heightScale = 8.0f});
    HeightField p = proceduralTerrain({.width = 512, .height = 512, .seed = 7});
    std::vector<float> k = loadPermeabilityMap("soil.png", t.width, t.height, mmPerHourToMetresPerSecond(20));
    std::vector<float> k2 = proceduralPermeability(p, {});  // m/s per cell
    // [/snippet]
    return t.width == 32 && t.height == 16 && k.size() == 32 * 16 && k2.size() == p.cellCount() ? 0 : 1;
}
