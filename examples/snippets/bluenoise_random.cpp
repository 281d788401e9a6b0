// The usage example of prism/bluenoise/random.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/bluenoise/random.hpp"
// [/snippet]

int main() {
    // [snippet]
    std::uint32_t h = prism::bluenoise::pcgHash(42u);  // same bits as GLSL prism_bn_pcg(42u)
    prism::bluenoise::SplitMix64 rng(7);               // deterministic per seed
    std::uint64_t a = rng.next();
    double u = rng.uniform();                    // in [0, 1)
    float f = prism::bluenoise::toUnitFloat(h);  // top 24 bits / 2^24, exact in float
    // [/snippet]
    // Reference values computed independently (Python, 32/64-bit wrapping arithmetic).
    return h == 1223963391u && a == 7191089600892374487ull && u >= 0.0 && u < 1.0 &&
                   f == static_cast<float>(1223963391u >> 8) / 16777216.0f
               ? 0
               : 1;
}
