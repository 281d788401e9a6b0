// rain_update: one simulation step of every particle (see modules/rain/particles.glsl);
// dispatched as ceil(count / 256) work groups, split over x and y when above 65535.
#version 430 core
#include <rain/particles.glsl>
#pragma prism targets gl spirv  // ES 3.00 has no compute stage

layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer RainParticles {
    RainParticle particles[];
};

uniform vec3 u_cylinderCenter;
uniform vec2 u_cylinder;
uniform float u_dt;
uniform vec3 u_wind;
uniform float u_fallSpeed;
uniform uint u_particleCount;
uniform float u_shearHeight;

void main() {
    uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
    if (i >= u_particleCount) return;
    particles[i] = rainStepParticle(particles[i], u_cylinderCenter, u_dt, u_wind, u_cylinder, u_fallSpeed,
                                    u_shearHeight);
}
