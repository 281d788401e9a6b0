// Content hashes (see content_hash.hpp).
#include "content_hash.hpp"

#include <cstdio>
#include <cstring>

namespace prism::shaderc {

ContentHash& ContentHash::add(std::string_view part) {
    // Eight bytes a step: two multiply-xorshift lanes with their own constants.
    const auto mix = [&](std::uint64_t word) {
        a_ = (a_ ^ word) * 0x9e3779b97f4a7c15ull;
        a_ ^= a_ >> 32;
        b_ = (b_ ^ word) * 0xc2b2ae3d27d4eb4full + 0x165667b19e3779f9ull;
        b_ ^= b_ >> 29;
    };
    std::size_t i = 0;
    for (; i + 8 <= part.size(); i += 8) {
        std::uint64_t word;
        std::memcpy(&word, part.data() + i, 8);
        mix(word);
    }
    std::uint64_t tail = 0;
    if (i < part.size()) std::memcpy(&tail, part.data() + i, part.size() - i);
    mix(tail);
    mix(static_cast<std::uint64_t>(part.size()) ^ 0xff00000000000000ull);  // the separator
    return *this;
}

std::string ContentHash::hex() const {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(a_),
                  static_cast<unsigned long long>(b_));
    return buf;
}

}  // namespace prism::shaderc
