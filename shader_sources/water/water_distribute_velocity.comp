// Water step 4a, distribution (RainCL §4.2.5, Algorithm 1, after Mueller's height-field
// fluid) written per von Neumann edge so that it conserves mass: each cell owns the
// velocity of its east and south edge (q > 0: water moves from this cell to the
// neighbour). q += c^2/h^2 (s_a - s_b) dt, times the damping factor; the epsilon rule:
// an edge whose receiving cell stands epsilon or more above the giving cell's surface
// carries nothing (water accumulations never climb); and a cell gives at most a quarter
// of its water per edge and step (no negative water, no overshoot).
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_TERRAIN) readonly buffer Terrain { float terrain[]; };
layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_VELOCITY) buffer Velocity { vec2 velocity[]; };

uniform float u_waveAccelDt;  // c^2 / h^2 x dt
uniform float u_damping;      // velocity factor per step, exp(-damping x dt)
uniform float u_epsilon;      // m
uniform float u_capPerDt;     // 0.24 / dt: a quarter of the available water per edge (less a margin)

float edgeVelocity(float q0, float sa, float sb, float availA, float availB) {
    precise float q = (q0 + u_waveAccelDt * (sa - sb)) * u_damping;
    if (q > 0.0 ? (sb >= sa + u_epsilon) : (sa >= sb + u_epsilon)) q = 0.0;
    precise float capA = availA * u_capPerDt;
    precise float capB = availB * u_capPerDt;
    return q > 0.0 ? min(q, capA) : max(q, -capB);
}

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    vec2 wi = waterIn[i];
    precise float si = terrain[i] + wi.x;
    float ai = availableWater(wi);
    vec2 q = velocity[i];
    if (c.x + 1 < u_gridSize.x) {
        int j = i + 1;
        vec2 wj = waterIn[j];
        precise float sj = terrain[j] + wj.x;
        q.x = edgeVelocity(q.x, si, sj, ai, availableWater(wj));
    }
    if (c.y + 1 < u_gridSize.y) {
        int j = i + u_gridSize.x;
        vec2 wj = waterIn[j];
        precise float sj = terrain[j] + wj.x;
        q.y = edgeVelocity(q.y, si, sj, ai, availableWater(wj));
    }
    velocity[i] = q;
}
