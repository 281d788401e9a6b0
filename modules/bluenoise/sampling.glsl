// Provides: per-pixel random numbers for Monte Carlo effects behind one function,
// prismBlueNoiseSample(pixel, frame, dim), bit-identical to the C++ reference
// prism/bluenoise/samplers.hpp (tested in tests/bluenoise/test_sampling_glsl.cpp):
//   u_blueNoiseSampler 0 = white: PCG hash of pixel, frame and dimension;
//                      1 = blue noise: the mask u_blueNoiseMask (R32UI, rank * 2^32 / N)
//                          at the pixel shifted by dimension dim's R2 offset, plus
//                          frame * the step of dim's parity (2^32/phi even, 2^32 (sqrt(3)-1)
//                          odd) in wrapping integer arithmetic: each dimension is a 1D
//                          low-discrepancy sequence over frames, each pair spread in 2D;
//                      2 = sorted: the per-pixel seed u_blueNoiseSeeds (R32UI, written by
//                          the sorting/retargeting passes) hashed with dim, plus the same
//                          frame offset;
//                      3 = stack: slice (frame mod D) of a spatiotemporal stack of D masks,
//                          u_blueNoiseStack (R32UI, W x (H * D), slice after slice),
//                          D = u_blueNoiseStackDepth, at the pixel shifted by dim's R2
//                          offset, plus (frame / D) times dim's step.
// Integer arithmetic only, so frame 10^6 is as precise as frame 0. docs/bluenoise.md.
uniform usampler2D u_blueNoiseMask;
uniform usampler2D u_blueNoiseSeeds;
uniform usampler2D u_blueNoiseStack;
uniform int u_blueNoiseStackDepth;
uniform int u_blueNoiseSampler;

const uint PRISM_BN_R2_X = 0xC13FA9A9u;    // 2^32 / g, g the plastic number
const uint PRISM_BN_R2_Y = 0x91E10DA5u;    // 2^32 / g^2

const uint PRISM_BN_GOLDEN = 0x9E3779B9u;  // 2^32 / phi
const uint PRISM_BN_SQRT3 = 0xBB67AE86u;   // 2^32 (sqrt(3) - 1)
uint prismBlueNoiseTemporalStep(uint dim) { return (dim & 1u) != 0u ? PRISM_BN_SQRT3 : PRISM_BN_GOLDEN; }

// PCG hash (Jarzynski & Olano 2020).
uint prismBlueNoisePcg(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint prismBlueNoiseWhite(uvec2 pixel, uint frame, uint dim) {
    return prismBlueNoisePcg(prismBlueNoisePcg(prismBlueNoisePcg(prismBlueNoisePcg(pixel.x) + pixel.y) + frame) + dim);
}

uint prismBlueNoiseMask(uvec2 pixel, uint frame, uint dim) {
    uvec2 size = uvec2(textureSize(u_blueNoiseMask, 0));
    uvec2 offset = (((uvec2(dim * PRISM_BN_R2_X, dim * PRISM_BN_R2_Y) >> 16u) * size) >> 16u);
    uvec2 p = (pixel % size + offset) % size;
    return texelFetch(u_blueNoiseMask, ivec2(p), 0).r + frame * prismBlueNoiseTemporalStep(dim);
}

uint prismBlueNoiseSorted(uvec2 pixel, uint frame, uint dim) {
    uvec2 size = uvec2(textureSize(u_blueNoiseSeeds, 0));
    uint seed = texelFetch(u_blueNoiseSeeds, ivec2(pixel % size), 0).r;
    return prismBlueNoisePcg(prismBlueNoisePcg(seed) + dim) + frame * prismBlueNoiseTemporalStep(dim);
}

uint prismBlueNoiseStack(uvec2 pixel, uint frame, uint dim) {
    uint depth = uint(max(u_blueNoiseStackDepth, 1));
    uvec2 size = uvec2(textureSize(u_blueNoiseStack, 0)) / uvec2(1u, depth);
    uvec2 offset = (((uvec2(dim * PRISM_BN_R2_X, dim * PRISM_BN_R2_Y) >> 16u) * size) >> 16u);
    uvec2 p = (pixel % size + offset) % size;
    uint slice = frame % depth;
    return texelFetch(u_blueNoiseStack, ivec2(p.x, slice * size.y + p.y), 0).r +
           (frame / depth) * prismBlueNoiseTemporalStep(dim);
}

// The sample as 32 bits.
uint prismBlueNoiseSampleBits(uvec2 pixel, uint frame, uint dim) {
    if (u_blueNoiseSampler == 1) return prismBlueNoiseMask(pixel, frame, dim);
    if (u_blueNoiseSampler == 2) return prismBlueNoiseSorted(pixel, frame, dim);
    if (u_blueNoiseSampler == 3) return prismBlueNoiseStack(pixel, frame, dim);
    return prismBlueNoiseWhite(pixel, frame, dim);
}

// The sample in [0, 1): its top 24 bits / 2^24 (exact in float, never 1.0).
float prismBlueNoiseSample(uvec2 pixel, uint frame, uint dim) {
    return float(prismBlueNoiseSampleBits(pixel, frame, dim) >> 8u) * (1.0 / 16777216.0);
}
