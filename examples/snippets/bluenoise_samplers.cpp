// The usage example of prism/bluenoise/samplers.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/bluenoise/samplers.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
// [/snippet]

int main() {
    // [snippet]
    namespace bn = prism::bluenoise;
    bn::Mask mask = bn::generateVoidAndCluster({.width = 16, .height = 16});
    bn::SamplerTables tables = bn::SamplerTables::fromMask(mask);
    std::uint32_t w = bn::sample(bn::SamplerKind::White, tables, 10, 20, 7, 0);  // pixel (10, 20), frame 7, dim 0
    std::uint32_t b = bn::sample(bn::SamplerKind::BlueNoise, tables, 10, 20, 7, 1);
    float u = bn::toUnitFloat(b);  // [0, 1)
    // [/snippet]
    // White: the hash chain of the header comment.
    const std::uint32_t white = bn::pcgHash(bn::pcgHash(bn::pcgHash(bn::pcgHash(10u) + 20u) + 7u) + 0u);
    // BlueNoise, dim 1: R2 offset of index 1 on a 16x16 mask is (0xC13F * 16 >> 16, 0x91E1 * 16 >> 16)
    // = (12, 9), so pixel (10, 20) reads the mask at ((10 + 12) mod 16, (20 + 9) mod 16) = (6, 13),
    // as a 32-bit fraction (rank * 2^32 / 256), plus frame 7 times the odd-dimension step.
    const std::uint32_t blue = (mask.rankAt(6, 13) << 24) + 7u * bn::kSqrt3Step;
    return w == white && b == blue && u >= 0.0f && u < 1.0f ? 0 : 1;
}
