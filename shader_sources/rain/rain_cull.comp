// rain_cull: keeps only the particles whose streak can reach a pixel of this view: it copies them, in their
// original order, into the draw buffer and writes one indirect draw command per block of particles, so
// particles outside the view frustum cost no vertex, geometry or fragment work.
// Each invocation tests a run of RAIN_CULL_RUN particles; a work group's runs make one block.
#version 430 core
#include <rain/particles.glsl>
#include <rain/streak_geometry.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage

const uint RAIN_CULL_RUN = 16u;  // particles per invocation; RainSystem's kCullBlock = 64 x 16
layout(local_size_x = 64) in;

struct RainDrawCommand {  // DrawArraysIndirectCommand
    uint count;
    uint instanceCount;
    uint first;
    uint baseInstance;
};

layout(std430, binding = 0) readonly buffer RainParticles {
    RainParticle particles[];
};
layout(std430, binding = 1) writeonly buffer RainVisibleParticles {
    RainParticle visible[];
};
// Per block: [block] the points command (GS quads, point sprites), [blocks + block] the instanced one.
layout(std430, binding = 2) writeonly buffer RainDrawCommands {
    RainDrawCommand commands[];
};

uniform uint u_particleCount;
uniform float u_maxStreakLength;  // m

shared uint s_runFirst[64];

// Conservative: a sphere around the drop's head as large as the longest streak any drop can draw
// (u_maxStreakLength: the fastest fall since the start plus jitter and wind, times the exposure) plus
// half the widest width it can be drawn with (see rainStreak, with the level-of-detail widening),
// against the six planes of viewProjection;
// only the position is read. Faint drops are left to the streak stages (they emit nothing): testing
// them here would cost every particle the full streak set-up.
bool rainStreakReachesView(vec3 head, mat4 viewProjection) {
    float farthest = length(u_cameraPosition - head) + u_maxStreakLength;
    float pixel = 2.0 * farthest / (max(u_projection[1][1], 1e-6) * max(u_viewportHeight, 1.0));
    float widest = pow(u_lod.y, (1.0 - max(u_lod.x, 1.0)) * 2.0 / 3.0);  // the largest level-of-detail widening
    float radius =
        u_maxStreakLength + 0.5 * widest * max(u_streakWidth.x + u_streakWidth.y * farthest, 1.5 * pixel) + 1e-3;
    vec3 centre = head;
    vec4 w = vec4(viewProjection[0][3], viewProjection[1][3], viewProjection[2][3], viewProjection[3][3]);
    for (int axis = 0; axis < 3; ++axis) {
        vec4 row = vec4(viewProjection[0][axis], viewProjection[1][axis], viewProjection[2][axis],
                        viewProjection[3][axis]);
        vec4 lower = w + row;
        vec4 upper = w - row;
        if (dot(lower.xyz, centre) + lower.w < -radius * length(lower.xyz)) return false;
        if (dot(upper.xyz, centre) + upper.w < -radius * length(upper.xyz)) return false;
    }
    return true;
}

void main() {
    uint lane = gl_LocalInvocationID.x;
    uint blocks = gl_NumWorkGroups.x;
    uint block = gl_WorkGroupID.x;
    uint blockFirst = block * gl_WorkGroupSize.x * RAIN_CULL_RUN;
    uint runFirst = blockFirst + lane * RAIN_CULL_RUN;
    mat4 viewProjection = u_projection * u_view;
    uint mask = 0u;
    uint kept = 0u;
    for (uint k = 0u; k < RAIN_CULL_RUN; ++k) {
        uint i = runFirst + k;
        if (i < u_particleCount && rainStreakReachesView(particles[i].position.xyz, viewProjection)) {
            mask |= 1u << k;
            ++kept;
        }
    }
    s_runFirst[lane] = kept;
    barrier();
    if (lane == 0u) {  // exclusive prefix sum over the runs: the block keeps the particles' order
        uint sum = 0u;
        for (uint l = 0u; l < gl_WorkGroupSize.x; ++l) {
            uint n = s_runFirst[l];
            s_runFirst[l] = sum;
            sum += n;
        }
        commands[block] = RainDrawCommand(sum, 1u, blockFirst, 0u);
        commands[blocks + block] = RainDrawCommand(4u, sum, 0u, blockFirst);
    }
    barrier();
    uint slot = blockFirst + s_runFirst[lane];
    for (uint k = 0u; k < RAIN_CULL_RUN; ++k) {
        if ((mask & (1u << k)) != 0u) visible[slot++] = particles[runFirst + k];
    }
}
