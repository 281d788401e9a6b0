// Conversions of a rank mask to quantized and fixed-point values.
#include "prism/bluenoise/mask.hpp"

#include <stdexcept>
#include <string>

namespace prism::bluenoise {

std::vector<std::uint16_t> quantize(const Mask& mask, int bits) {
    if (bits < 1 || bits > 16)
        throw std::invalid_argument("prism::bluenoise::quantize: bits must be 1..16, got " + std::to_string(bits));
    std::vector<std::uint16_t> out(mask.size());
    const std::uint64_t n = mask.size();
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<std::uint16_t>((static_cast<std::uint64_t>(mask.rank[i]) << bits) / n);
    return out;
}

std::vector<std::uint32_t> fixedPoint32(const Mask& mask) {
    std::vector<std::uint32_t> out(mask.size());
    const std::uint64_t n = mask.size();
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(mask.rank[i]) << 32) / n);
    return out;
}

std::vector<std::uint32_t> goldenRatioSlice(const Mask& mask, std::uint32_t frame) {
    std::vector<std::uint32_t> out = fixedPoint32(mask);
    const std::uint32_t offset = frame * kGoldenRatioStep;  // wraps mod 2^32
    for (std::uint32_t& v : out) v += offset;
    return out;
}

}  // namespace prism::bluenoise
