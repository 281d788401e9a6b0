// Terrain height fields and permeability ("attribute") maps for the water system:
// loaded from 8- or 16-bit PNG files with Prism's own libpng read path (prism::image::readPng
// would reduce 16-bit maps to 8 bits), or generated procedurally.
//
// Usage (snippet: examples/snippets/water_height_field.cpp):
//
//     #include "prism/water/height_field.hpp"
//     using namespace prism::water;
//     HeightField t = loadHeightMap("terrain.png", {.cellSize = 0.25f, .heightScale = 8.0f});
//     HeightField p = proceduralTerrain({.width = 512, .height = 512, .seed = 7});
//     std::vector<float> k = loadPermeabilityMap("soil.png", t.width, t.height, mmPerHourToMetresPerSecond(20));
//     std::vector<float> k2 = proceduralPermeability(p, {});  // m/s per cell
//
// Grid layout: row-major, x across, z down; cell (x, z) is pixel (x, z) of the PNG
// (row 0 = top row) and sits at local position (x h, height, z h). Maps may be
// rectangular. Colour PNGs use their first (red) channel, as RainCL's scalar maps do (§4.2.3);
// an alpha channel is ignored. Palette images and 1/2/4-bit images are rejected.
// Every load error is a HeightMapError whose message starts with the file name; so is a
// map larger than kMaxMapSide a side or kMaxMapCells in all (checked before any pixel
// memory is allocated).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace prism::water {

// Limits on loaded maps (docs/reliability.md): 16384 a side and 2^26 (8192^2) cells.
inline constexpr std::uint32_t kMaxMapSide = 16384;
inline constexpr std::uint64_t kMaxMapCells = std::uint64_t{1} << 26;

class HeightMapError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct HeightField {
    int width = 0;
    int height = 0;
    float cellSize = 1.0f;       // metres between neighbouring cells (h), in (0, kMaxCellSize]
    std::vector<float> heights;  // metres above `origin`, width * height, row-major, |h| <= kMaxHeight
    double origin = 0.0;         // metres: the world height of height 0 (a local origin, so terrain
                                 // high above sea level keeps fp32 precision near its ground)

    std::size_t cellCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    std::size_t index(int x, int z) const {
        return static_cast<std::size_t>(z) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    }
    float at(int x, int z) const { return heights[index(x, z)]; }
    // Size of the covered area in metres (cell centres span (width - 1) h).
    float sizeX() const { return static_cast<float>(width > 0 ? width - 1 : 0) * cellSize; }
    float sizeZ() const { return static_cast<float>(height > 0 ? height - 1 : 0) * cellSize; }
};

inline constexpr float kMaxCellSize = 1.0e4f;  // m
inline constexpr float kMaxHeight = 1.0e6f;    // m, |height| relative to the origin
// Throws std::invalid_argument when sizes, cell size, heights or origin are not usable
// (not finite, or beyond kMaxCellSize / kMaxHeight).
void validate(const HeightField& field, const char* what);

// A single-channel image of 8- or 16-bit samples (values 0..255 or 0..65535).
struct GreyImage {
    int width = 0;
    int height = 0;
    int bitDepth = 8;
    std::vector<std::uint16_t> values;  // width * height, row 0 = top
    double maxValue() const { return bitDepth == 16 ? 65535.0 : 255.0; }
};

// Reads the first channel of an 8- or 16-bit grey, grey+alpha, RGB or RGBA PNG.
GreyImage readGreyPng(const std::filesystem::path& path);
// Writes an 8- or 16-bit greyscale PNG (for tests, examples and tools).
void writeGreyPng(const std::filesystem::path& path, const GreyImage& image);

struct HeightMapOptions {
    float cellSize = 0.25f;    // metres per pixel, (0, kMaxCellSize]
    float heightScale = 8.0f;  // metres for the largest sample value (255 or 65535), |scale| <= kMaxHeight
    float baseHeight = 0.0f;   // metres for sample value 0: becomes the field's origin
};
HeightField loadHeightMap(const std::filesystem::path& path, const HeightMapOptions& options = {});

struct ProceduralTerrainOptions {
    int width = 512;
    int height = 512;
    float cellSize = 0.125f;  // 512 cells: a 64 m square
    float relief = 3.0f;      // metres between the lowest and highest fBm hills
    int pits = 7;             // bowls where puddles collect
    unsigned seed = 1;
};
// Rolling hills (value-noise fBm) with a gentle tilt towards one edge and a few
// bowl-shaped depressions; deterministic for a seed on every platform.
HeightField proceduralTerrain(const ProceduralTerrainOptions& options = {});

// --- Permeability (the attribute map of RainCL §4.2.3): maximum infiltration rate, m/s, per cell ---

// Sample value v of the PNG maps to maxRate * v / maxValue. The image must have the
// terrain's size; otherwise a HeightMapError names the file and both sizes.
std::vector<float> loadPermeabilityMap(const std::filesystem::path& path, int width, int height,
                                       double maxRateMetresPerSecond);

struct PermeabilityOptions {
    double soilMmPerHour = 12.0;  // loose soil
    double clayMmPerHour = 0.5;   // compacted ground, clay and rock: puddles form here
    unsigned seed = 11;
};
// Patches of soil and compacted ground from value noise, with steep ground compacted.
std::vector<float> proceduralPermeability(const HeightField& terrain, const PermeabilityOptions& options = {});
std::vector<float> uniformPermeability(const HeightField& terrain, double metresPerSecond);

// Value noise in [0, 1) at integer lattice points and its smooth fBm, used by the
// procedural terrain, permeability and sky.
float latticeNoise(int x, int y, int z, unsigned seed);
float valueNoise3(float x, float y, float z, unsigned seed);
float fbm3(float x, float y, float z, unsigned seed, int octaves);

}  // namespace prism::water
