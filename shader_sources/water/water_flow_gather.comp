// Water step 3b, tangential flow: every cell gives its amount to its target and takes
// what the Moore neighbours that point at it give (a gather, so no atomics and the
// same summation order as the CPU). Amounts aimed outside the grid leave through the
// border and are added to the cell's ledger accumulator.
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_WATER_OUT) writeonly buffer WaterOut { vec2 waterOut[]; };
layout(std430, binding = WATER_BINDING_FLOW) readonly buffer Flow { vec2 flow[]; };
layout(std430, binding = WATER_BINDING_LEDGER_CELLS) buffer LedgerCells { dvec2 ledgerCells[]; };  // (infiltrated, lost)

ivec2 directionOffset(int code) {
    return ivec2(code % 3 - 1, code / 3 - 1);
}

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    vec2 own = flow[i];
    int code = int(own.y);
    precise float net = 0.0;
    float lost = 0.0;
    if (code != 4 && own.x > 0.0) {
        net = -own.x;
        if (!insideGrid(c + directionOffset(code))) lost = own.x;
    }
    for (int oz = -1; oz <= 1; ++oz) {
        for (int ox = -1; ox <= 1; ++ox) {
            if (ox == 0 && oz == 0) continue;
            ivec2 nc = c + ivec2(ox, oz);
            if (!insideGrid(nc)) continue;
            vec2 f = flow[cellIndex(nc)];
            int ncode = int(f.y);
            if (ncode != 4 && directionOffset(ncode) == ivec2(-ox, -oz)) net = net + f.x;
        }
    }
    waterOut[i] = dfAdd(waterIn[i], net);
    if (lost > 0.0) ledgerCells[i].y += double(lost);
}
