// Provides: the counter-based hash RNG of the rain system, bit-identical to the C++
// reference (prism/rain/random.hpp): pcgHash (the PCG output permutation as a hash,
// Jarzynski & Olano 2020), rainRandom(seed, index, channel) and rainUniform() in [0, 1)
// with 24 bits of resolution (exact in float on every device).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// One 32-bit random number per (seed, particle index, channel): no state, no order.
uint rainRandom(uint seed, uint index, uint channel) {
    return pcgHash(pcgHash(pcgHash(seed) + index) ^ (channel * 0x9E3779B9u));
}

float rainUniform(uint seed, uint index, uint channel) {
    return float(rainRandom(seed, index, channel) >> 8u) * (1.0 / 16777216.0);
}
