// Provides: the water simulation's grid helpers for the compute passes: storage-buffer
// binding points (must match runtime/water/src/gpu_water_simulation.cpp), cell indexing,
// the compensated (hi, lo) water height with its exact addition dfAdd(), the water a cell
// may give away this pass (availableWater) and the free surface terrain + water.
// All arithmetic is fp32 and `precise`, in the same order as the CPU reference
// (runtime/water/src/cpu_water_simulation.cpp), so the two agree to the last bit when
// the driver honours IEEE rounding.

#define WATER_BINDING_TERRAIN 0
#define WATER_BINDING_PERMEABILITY 1
#define WATER_BINDING_WATER_IN 2
#define WATER_BINDING_WATER_OUT 3
#define WATER_BINDING_VELOCITY 4
#define WATER_BINDING_FLOW 5
#define WATER_BINDING_LEDGER_CELLS 6
#define WATER_BINDING_LEDGER_PARTIALS 7
#define WATER_BINDING_LEDGER_TOTALS 8

uniform ivec2 u_gridSize;

bool insideGrid(ivec2 c) {
    return c.x >= 0 && c.y >= 0 && c.x < u_gridSize.x && c.y < u_gridSize.y;
}

int cellIndex(ivec2 c) {
    return c.y * u_gridSize.x + c.x;
}

ivec2 clampToGrid(ivec2 c) {
    return clamp(c, ivec2(0), u_gridSize - ivec2(1));
}

// s + e == a + b exactly (Knuth's TwoSum); `precise` keeps the driver from simplifying it.
vec2 twoSum(float a, float b) {
    precise float s = a + b;
    precise float bb = s - a;
    precise float e = (a - (s - bb)) + (b - bb);
    return vec2(s, e);
}

// (hi, lo) + d, renormalised so that |lo| <= ulp(hi) / 2: the rounding error of every
// update is kept in lo instead of being lost, so tiny rain increments on deep water
// add up exactly (no fp32 drift in the mass ledger).
vec2 dfAdd(vec2 w, float d) {
    vec2 t = twoSum(w.x, d);
    precise float lo = t.y + w.y;
    precise float hi = t.x + lo;
    precise float lo2 = lo - (hi - t.x);
    return vec2(hi, lo2);
}

// What a cell may give away in one pass: its water less 2^-20 of it, which covers the
// rounding of the few fp32 operations between this bound and the update, so no cell
// is ever driven below zero.
const float WATER_AVAILABLE_FACTOR = 0.99999904632568359375;  // 1 - 2^-20, exact in fp32

float availableWater(vec2 w) {
    precise float v = w.x + w.y;
    precise float a = v * WATER_AVAILABLE_FACTOR;
    return v > 0.0 ? a : 0.0;
}
