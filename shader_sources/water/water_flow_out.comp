// Water step 3a, tangential flow (RainCL §4.2.4, Listing 4): the Sobel gradient of the free
// surface (terrain + water, clamped at the border) picks the downhill Moore neighbour;
// the amount is the cell's water times min(maxFraction, flowRate * dt * |slope|), never
// more than half the surface drop to that neighbour (no overshoot uphill). Writes
// (amount, direction code 0..8, 4 = none) for the gather pass.
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_TERRAIN) readonly buffer Terrain { float terrain[]; };
layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_FLOW) writeonly buffer Flow { vec2 flow[]; };

uniform float u_invEightCell;     // 1 / (8 h): Sobel sum -> slope
uniform float u_flowRateDt;       // flow rate (1/s per unit slope) x dt
uniform float u_maxFlowFraction;  // at most this share of a cell's water per step
uniform int u_openBorder;         // 1: water whose downhill neighbour is outside leaves

const float TAN_22_5 = 0.41421356;  // sector boundary between axis and diagonal neighbours

float surfaceAt(ivec2 c) {
    int j = cellIndex(clampToGrid(c));
    precise float s = terrain[j] + waterIn[j].x;
    return s;
}

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    float nw = surfaceAt(c + ivec2(-1, -1)), n = surfaceAt(c + ivec2(0, -1)), ne = surfaceAt(c + ivec2(1, -1));
    float w = surfaceAt(c + ivec2(-1, 0)), e = surfaceAt(c + ivec2(1, 0));
    float sw = surfaceAt(c + ivec2(-1, 1)), s = surfaceAt(c + ivec2(0, 1)), se = surfaceAt(c + ivec2(1, 1));
    precise float gx = ((ne + 2.0 * e + se) - (nw + 2.0 * w + sw)) * u_invEightCell;
    precise float gz = ((sw + 2.0 * s + se) - (nw + 2.0 * n + ne)) * u_invEightCell;
    precise float slope = sqrt(gx * gx + gz * gz);
    float dx = -gx, dz = -gz;  // downhill
    int ox = abs(dx) > TAN_22_5 * abs(dz) ? int(sign(dx)) : 0;
    int oz = abs(dz) > TAN_22_5 * abs(dx) ? int(sign(dz)) : 0;
    vec2 result = vec2(0.0, 4.0);
    ivec2 t = c + ivec2(ox, oz);
    bool inside = insideGrid(t);
    if ((ox != 0 || oz != 0) && slope > 0.0 && (inside || u_openBorder != 0)) {
        vec2 wi = waterIn[i];
        precise float si = terrain[i] + wi.x;
        precise float st = inside ? terrain[cellIndex(t)] + waterIn[cellIndex(t)].x : terrain[i];
        precise float fraction = min(u_maxFlowFraction, u_flowRateDt * slope);
        precise float amount = min(fraction * availableWater(wi), max(0.0, (si - st) * 0.5));
        result = vec2(amount, float((oz + 1) * 3 + (ox + 1)));
    }
    flow[i] = result;
}
