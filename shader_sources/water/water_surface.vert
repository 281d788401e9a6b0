// Water surface: one vertex per water-map cell, addressed by gl_VertexID (the mesh is
// only an index buffer). A wet vertex sits on the water surface (terrain + depth). A dry
// vertex next to water continues the neighbouring water level into the bank, so the
// surface meets the terrain along the true contour line (the depth test and the
// fragment's own depth cut it there) instead of in cell-sized steps, but never rises above
// its own ground (downhill of a wet cell on a slope it would otherwise lift a cell-sized
// sheet of deep-looking water); a dry vertex away from water is tucked under the terrain. The normal comes from central differences of
// the surface.
#include <version.glsl>
#include <transforms.glsl>

uniform sampler2D u_terrainHeight;  // R32F terrain height per cell
uniform sampler2D u_waterDepth;     // RG32F compensated depth (hi, lo) per cell
uniform float u_cellSize;
uniform float u_waterThreshold;     // m: a vertex with less water is dry (the surface fades in from 0 m)

out vec3 v_worldPosition;
out vec3 v_eyePosition;
out vec3 v_worldNormal;
out float v_depth;    // water level minus terrain (m): negative under a bank
out vec2 v_uv;        // grid position as texture coordinate (texel centres)

float depthAt(ivec2 c) {
    vec2 w = texelFetch(u_waterDepth, c, 0).rg;
    return w.x + w.y;
}

// Surface height of a wet neighbour; a dry one (or one outside) continues the centre.
float neighbourSurface(ivec2 c, ivec2 size, float centre) {
    if (c.x < 0 || c.y < 0 || c.x >= size.x || c.y >= size.y) return centre;
    float d = depthAt(c);
    return d > u_waterThreshold ? texelFetch(u_terrainHeight, c, 0).r + d : centre;
}

void main() {
    ivec2 size = textureSize(u_terrainHeight, 0);
    ivec2 c = ivec2(gl_VertexID % size.x, gl_VertexID / size.x);
    float ground = texelFetch(u_terrainHeight, c, 0).r;
    float depth = depthAt(c);
    bool wet = depth > u_waterThreshold;
    float surface = ground + depth;
    float y = ground - 0.25 * u_cellSize;
    if (wet) {
        y = surface;
    } else {
        float level = -1.0e30;
        for (int k = 0; k < 4; ++k) {
            ivec2 o = k == 0 ? ivec2(1, 0) : k == 1 ? ivec2(-1, 0) : k == 2 ? ivec2(0, 1) : ivec2(0, -1);
            ivec2 nc = clamp(c + o, ivec2(0), size - ivec2(1));
            float d = depthAt(nc);
            if (d > u_waterThreshold) level = max(level, texelFetch(u_terrainHeight, nc, 0).r + d);
        }
        if (level > -1.0e29) y = min(level, ground);
    }
    vec3 normal = vec3(0.0, 1.0, 0.0);
    if (wet) {
        float e = neighbourSurface(c + ivec2(1, 0), size, surface);
        float w = neighbourSurface(c - ivec2(1, 0), size, surface);
        float s = neighbourSurface(c + ivec2(0, 1), size, surface);
        float n = neighbourSurface(c - ivec2(0, 1), size, surface);
        normal = vec3(w - e, 2.0 * u_cellSize, n - s);
    }
    vec4 world = u_world * vec4(float(c.x) * u_cellSize, y, float(c.y) * u_cellSize, 1.0);
    vec4 eye = u_view * world;
    v_worldPosition = world.xyz;
    v_eyePosition = eye.xyz;
    v_worldNormal = mat3(u_world) * normal;
    v_depth = y - ground;
    v_uv = (vec2(c) + 0.5) / vec2(size);
    gl_Position = clipPosition(eye);
}
