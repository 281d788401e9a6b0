// rain_init: seeds particles [u_firstParticle, u_particleCount) around the cylinder
// centre (see rainSeedParticle in modules/rain/particles.glsl); the C++ reference
// seeds identically, so both start from the same state.
#version 430 core
#include <rain/particles.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage

layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer RainParticles {
    RainParticle particles[];
};

uniform vec3 u_cylinderCenter;
uniform vec2 u_cylinder;
uniform vec2 u_lod;
uniform vec3 u_wind;
uniform float u_fallSpeed;
uniform float u_jitter;
uniform uint u_rainSeed;
uniform uint u_firstParticle;
uniform uint u_particleCount;
uniform float u_shearHeight;

void main() {
    uint i = u_firstParticle + gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) +
             gl_GlobalInvocationID.x;
    if (i >= u_particleCount) return;
    particles[i] = rainSeedParticle(i, u_rainSeed, u_cylinderCenter, u_cylinder, u_lod, u_fallSpeed, u_jitter, u_wind,
                                    u_shearHeight);
}
