// Mass ledger, GPU side, part 2: one work group sums the per-group partial sums (fixed
// order, double precision) into the totals (infiltrated, lost through the border).
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 256) in;

layout(std430, binding = WATER_BINDING_LEDGER_PARTIALS) readonly buffer LedgerPartials { dvec2 partials[]; };
layout(std430, binding = WATER_BINDING_LEDGER_TOTALS) buffer LedgerTotals { dvec2 totals; };

uniform int u_partialCount;

shared dvec2 sums[256];

void main() {
    uint k = gl_LocalInvocationIndex;
    dvec2 s = dvec2(0.0);
    for (uint j = k; j < uint(u_partialCount); j += 256u) s += partials[j];
    sums[k] = s;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u) {
        if (k < stride) sums[k] += sums[k + stride];
        barrier();
    }
    if (k == 0u) totals = sums[0];
}
