// Integer hashes and a seeded generator shared by the CPU code and modules/bluenoise/sampling.glsl.
//
// Usage (snippet: examples/snippets/bluenoise_random.cpp):
//
//     #include "prism/bluenoise/random.hpp"
//     std::uint32_t h = prism::bluenoise::pcgHash(42u);  // same bits as GLSL prism_bn_pcg(42u)
//     prism::bluenoise::SplitMix64 rng(7);               // deterministic per seed
//     std::uint64_t a = rng.next();
//     double u = rng.uniform();                    // in [0, 1)
//     float f = prism::bluenoise::toUnitFloat(h);  // top 24 bits / 2^24, exact in float
//
// pcgHash is the "PCG hash" of Jarzynski & Olano (JCGT 2020): one LCG step followed by
// the PCG RXS-M-XS output permutation, on 32-bit unsigned integers that wrap, so GLSL
// `uint` arithmetic gives the same bits.
#pragma once

#include <cstdint>

namespace prism::bluenoise {

constexpr std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// 32-bit sample -> float in [0, 1): the top 24 bits, so the result is exact in float and
// never rounds up to 1.
constexpr float toUnitFloat(std::uint32_t v) {
    return static_cast<float>(v >> 8u) * (1.0f / 16777216.0f);
}

// SplitMix64 (Steele, Lea & Flood 2014): the generator behind every --seed.
class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
    // Uniform integer in [0, n), n > 0 (multiply-shift; bias below 2^-32 for n < 2^32).
    std::uint64_t below(std::uint64_t n) { return static_cast<std::uint64_t>(uniform() * static_cast<double>(n)); }

  private:
    std::uint64_t state_;
};

}  // namespace prism::bluenoise
