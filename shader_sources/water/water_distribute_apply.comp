// Water step 4b, distribution: moves q x dt across each of the cell's four edges (its
// own east/south edges and the west/north neighbours' ones). Both cells of an edge
// compute the same fp32 product, so what one loses the other gains exactly.
#version 430 core
#include <water/water_grid.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = WATER_BINDING_WATER_IN) readonly buffer WaterIn { vec2 waterIn[]; };
layout(std430, binding = WATER_BINDING_WATER_OUT) writeonly buffer WaterOut { vec2 waterOut[]; };
layout(std430, binding = WATER_BINDING_VELOCITY) readonly buffer Velocity { vec2 velocity[]; };

uniform float u_dt;

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (!insideGrid(c)) return;
    int i = cellIndex(c);
    vec2 q = velocity[i];
    precise float te = c.x + 1 < u_gridSize.x ? q.x * u_dt : 0.0;
    precise float ts = c.y + 1 < u_gridSize.y ? q.y * u_dt : 0.0;
    precise float tw = c.x > 0 ? velocity[i - 1].x * u_dt : 0.0;
    precise float tn = c.y > 0 ? velocity[i - u_gridSize.x].y * u_dt : 0.0;
    precise float net = (tw + tn) - (te + ts);
    waterOut[i] = dfAdd(waterIn[i], net);
}
