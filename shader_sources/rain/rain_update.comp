// rain_update: one simulation step of every particle (see modules/rain/particles.glsl);
// dispatched as ceil(count / 256) work groups, split over x and y when above 65535. Reads and stores
// only the fields a step uses and changes.
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
    // Most drops neither leave the cylinder nor respawn in a step: for them only the position and the
    // velocity are read and only the position is stored, by the same formula as rainStepParticle.
    vec3 moved = particles[i].position.xyz + (particles[i].velocity.xyz + u_wind) * u_dt;
    vec3 local = moved - u_cylinderCenter;
    if (local.y >= -0.5 * u_cylinder.y && local.y < 0.5 * u_cylinder.y && length(local.xz) <= u_cylinder.x) {
        particles[i].position.xyz = u_cylinderCenter + local;
        return;
    }
    RainParticle p = particles[i];
    RainParticle stepped = rainStepParticle(p, u_cylinderCenter, u_dt, u_wind, u_cylinder, u_fallSpeed, u_shearHeight);
    // Only what a step changes is stored: the position, and the fall speed when the drop respawned
    // (the seed and the jitter never change).
    particles[i].position.xyz = stepped.position.xyz;
    if (stepped.velocity.y != p.velocity.y) particles[i].velocity.y = stepped.velocity.y;
}
