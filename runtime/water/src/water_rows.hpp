// The passes of one CPU water substep, each applied to one row of cells and given the rows
// it reads as pointers, so that the step (cpu_water_simulation.cpp) can run them fused:
// every pass on a row as soon as the rows it reads are done, with the intermediate rows
// kept in small per-thread rings instead of whole-grid arrays. A row's cells are computed
// with the same fp32 operations in the same order as the per-cell compute shaders of
// shader_sources/water/, whatever row they are given. Internal to prism_water.
//
//     detail::WaterRow out{hi, lo, surf, avail};
//     const double infiltrated = detail::rainRow(k, W, hiIn, loIn, permeability, terrain, out);
//     detail::flowOutRow(k, {W, H, z}, {surfNorth, surf, surfSouth}, avail, terrain, amount, code);
#pragma once

#include <cstdint>

#include "prism/water/water_simulation.hpp"

namespace prism::water::detail {

// Where a pass writes the water of a row: the compensated pair and the surface
// (terrain + hi) and available water that the next pass reads.
struct WaterRow {
    float* hi;
    float* lo;
    float* surf;
    float* avail;
};

// The row being computed and the grid around it.
struct RowAt {
    int width, height, z;
};

// Rows z - 1, z and z + 1 of one array, each clamped to the grid (row 0 is its own north
// neighbour, row H - 1 its own south one).
template <class T>
struct Rows3 {
    const T* north;
    const T* centre;
    const T* south;
};

// 1 + 2 (water_rain_infiltrate.comp); returns the depth the row lost to infiltration.
double rainRow(const StepConstants& k, int width, const float* hiIn, const float* loIn, const float* permeability,
               const float* terrain, WaterRow out);
// 3a (water_flow_out.comp): the amount each cell sends and the code of its target.
void flowOutRow(const StepConstants& k, RowAt at, Rows3<float> surf, const float* avail, const float* terrain,
                float* amount, std::int32_t* code);
// 3b (water_flow_gather.comp); returns the depth the row sent off the map.
double gatherRow(RowAt at, Rows3<float> amount, Rows3<std::int32_t> code, const float* hiIn, const float* loIn,
                 const float* terrain, WaterRow out);
// 4a (water_distribute_velocity.comp): the row's east and south edge velocities; the south
// edges of the last row and the east edge of the last column are copied unchanged.
void velocityRow(const StepConstants& k, RowAt at, const float* surf, const float* surfSouth, const float* avail,
                 const float* availSouth, const float* qEastIn, const float* qSouthIn, float* qEastOut,
                 float* qSouthOut);
// 4b (water_distribute_apply.comp); qSouthNorth is the row above's (unused on row 0).
void applyRow(const StepConstants& k, RowAt at, const float* qEast, const float* qSouth, const float* qSouthNorth,
              const float* hiIn, const float* loIn, const float* terrain, WaterRow out);
// 5 (water_smooth.comp), in two parts. An exchange between two cells is computed the same
// by both, up to sign (smoothExchange), so each pair is computed once: smoothPairsRow gives
// row z's exchange with each forward neighbour (dz > 0, or dz = 0 and dx > 0; offset f in
// smoothRow's order at pairs + f * width, for the cells whose neighbour is on the grid),
// and smoothRow adds them up per cell in the per-cell order, the backward ones negated
// from the rows above. surf[r + dz] and avail[r + dz] are rows z + dz for |dz| <= r
// (unused outside the grid); pairs[r + dz] is smoothPairsRow's row z + dz for dz in [-r, 0];
// net is scratch of `width` floats.
int forwardPairs(int radius);  // 2 r (r + 1) offsets
void smoothPairsRow(const StepConstants& k, RowAt at, const float* const* surf, const float* const* avail,
                    float* pairs);
void smoothRow(const StepConstants& k, RowAt at, const float* const* surf, const float* const* avail,
               const float* const* pairs, const float* hiIn, const float* loIn, const float* terrain, WaterRow out,
               float* net);

}  // namespace prism::water::detail
