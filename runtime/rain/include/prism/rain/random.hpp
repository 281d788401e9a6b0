// The rain system's counter-based random numbers, bit-identical to modules/rain/random.glsl:
// no state, one 32-bit value per (seed, index, channel), so the CPU reference and the
// GPU compute shader draw exactly the same numbers for the same particle.
//
// Usage (snippet: examples/snippets/rain_random.cpp):
//
//     #include "prism/rain/random.hpp"
//     std::uint32_t h = prism::rain::pcgHash(42u);                  // PCG output permutation
//     float u = prism::rain::rainUniform(seed, particle, channel);  // [0, 1), 24-bit steps
//
// pcgHash is the "pcg" hash of Jarzynski & Olano, "Hash Functions for GPU Rendering"
// (JCGT 2020): one LCG step followed by PCG's RXS-M-XS output permutation.
#pragma once

#include <cstdint>

namespace prism::rain {

constexpr std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

constexpr std::uint32_t rainRandom(std::uint32_t seed, std::uint32_t index, std::uint32_t channel) {
    return pcgHash(pcgHash(pcgHash(seed) + index) ^ (channel * 0x9E3779B9u));
}

// Exact in float: a 24-bit integer times 2^-24.
constexpr float rainUniform(std::uint32_t seed, std::uint32_t index, std::uint32_t channel) {
    return static_cast<float>(rainRandom(seed, index, channel) >> 8u) * (1.0f / 16777216.0f);
}

}  // namespace prism::rain
