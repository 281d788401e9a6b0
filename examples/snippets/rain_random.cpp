// The usage example of prism/rain/random.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/rain/random.hpp"
// [/snippet]

int main() {
    const std::uint32_t seed = 1, particle = 12, channel = 3;
    // [snippet]
    std::uint32_t h = prism::rain::pcgHash(42u);                  // PCG output permutation
    float u = prism::rain::rainUniform(seed, particle, channel);  // [0, 1), 24-bit steps
    // [/snippet]
    return h != 42u && u >= 0.0f && u < 1.0f ? 0 : 1;
}
