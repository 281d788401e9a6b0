// Water step 1 and 2 (RainCL §4.2.3): rain adds u_rainDepth (intensity x dt) to every
// cell, then infiltration removes permeability x dt, or all the water when that is as
// much (the compensated pair is emptied exactly, so the ground never goes below zero).
// Adds the infiltrated depth to the cell's double-precision ledger accumulator.
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_PERMEABILITY) readonly buffer Permeability { float permeability[]; };
layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_WATER_OUT) writeonly buffer WaterOut { vec2 waterOut[]; };
layout(std430, binding = WATER_BINDING_LEDGER_CELLS) buffer LedgerCells { dvec2 ledgerCells[]; };  // (infiltrated, lost)

uniform float u_rainDepth;  // m of rain this step
uniform float u_dt;

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    vec2 w = dfAdd(waterIn[i], u_rainDepth);
    precise float capacity = permeability[i] * u_dt;
    vec2 infiltrated;
    if (capacity >= availableWater(w)) {
        infiltrated = w;
        w = vec2(0.0);
    } else {
        infiltrated = vec2(capacity, 0.0);
        w = dfAdd(w, -capacity);
    }
    waterOut[i] = w;
    ledgerCells[i].x += double(infiltrated.x) + double(infiltrated.y);
}
