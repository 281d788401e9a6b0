// Mass ledger, GPU side, part 1 (run when the ledger is read): sums the per-cell
// double-precision totals of infiltrated and border-lost depth of 256 cells per work
// group (shared-memory tree) into one partial sum per group.
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 256) in;

layout(std430, binding = WATER_BINDING_LEDGER_CELLS) readonly buffer LedgerCells { dvec2 ledgerCells[]; };
layout(std430, binding = WATER_BINDING_LEDGER_PARTIALS) writeonly buffer LedgerPartials { dvec2 partials[]; };

shared dvec2 sums[256];

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint count = uint(u_gridSize.x) * uint(u_gridSize.y);
    sums[gl_LocalInvocationIndex] = i < count ? ledgerCells[i] : dvec2(0.0);
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u) {
        if (gl_LocalInvocationIndex < stride)
            sums[gl_LocalInvocationIndex] += sums[gl_LocalInvocationIndex + stride];
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u) partials[gl_WorkGroupID.x] = sums[0];
}
