// Water step 5: Gaussian smoothing of the free surface (RainCL §4.2.5, last paragraph) in
// flux form: every pair of cells within the kernel exchanges weight x (s_a - s_b),
// weight = strength x g(dx) g(dz) from the normalised 1D Gaussian g, limited to weight
// x the giver's water. Each pair's exchange is computed identically by both cells, so
// the smoothing conserves mass exactly; pairs reaching outside the grid do not exist
// (the border is a wall for the smoothing).
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_TERRAIN) readonly buffer Terrain { float terrain[]; };
layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_WATER_OUT) writeonly buffer WaterOut { vec2 waterOut[]; };

uniform int u_smoothRadius;         // kernel size = 2 r + 1, r <= 7
uniform float u_smoothWeights[64];  // [|dz| * 8 + |dx|]

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    vec2 wi = waterIn[i];
    precise float si = terrain[i] + wi.x;
    float ai = availableWater(wi);
    precise float net = 0.0;
    for (int dz = -u_smoothRadius; dz <= u_smoothRadius; ++dz) {
        for (int dx = -u_smoothRadius; dx <= u_smoothRadius; ++dx) {
            if (dx == 0 && dz == 0) continue;
            ivec2 nc = c + ivec2(dx, dz);
            if (!insideGrid(nc)) continue;
            int j = cellIndex(nc);
            float weight = u_smoothWeights[abs(dz) * 8 + abs(dx)];
            vec2 wj = waterIn[j];
            precise float sj = terrain[j] + wj.x;
            precise float t;
            if (si > sj) {
                precise float a = weight * (si - sj);
                precise float b = weight * ai;
                t = -min(a, b);
            } else {
                precise float a = weight * (sj - si);
                precise float b = weight * availableWater(wj);
                t = min(a, b);
            }
            net = net + t;
        }
    }
    waterOut[i] = dfAdd(wi, net);
}
